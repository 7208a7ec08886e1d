/* The fast mesh block stage on AVX-512 (fast_tmpl.h). */
#include "vec_avx512.h"
#define FAST_BLOCK mesh_fast_block_avx512
#include "fast_tmpl.h"
