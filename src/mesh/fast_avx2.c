/* The fast mesh block stage on AVX2 (fast_tmpl.h). */
#include "vec_avx2.h"
#define FAST_BLOCK mesh_fast_block_avx2
#include "fast_tmpl.h"
