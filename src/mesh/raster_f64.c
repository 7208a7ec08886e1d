/* The raster loop in binary64 (raster_tmpl.h). */
#define REAL double
#define RASTER_NAME mesh_raster_f64
#define RASTER_CH ch_f64
#define RASTER_FOG fog_f64
#include "raster_tmpl.h"
