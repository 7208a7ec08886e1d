/* The raster loop in binary32 (raster_tmpl.h). */
#define REAL float
#define RASTER_NAME mesh_raster_f32
#define RASTER_CH ch_f32
#define RASTER_FOG fog_f32
#include "raster_tmpl.h"
