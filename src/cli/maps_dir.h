/* Where retro verify and retro accuracy find their generated maps, in or outside the source
 * tree (an installed retro has no maps/ beside it). */
#ifndef RETRO_CLI_MAPS_DIR_H
#define RETRO_CLI_MAPS_DIR_H

#include <stddef.h>

/* Chooses the maps folder into dir (n bytes): `given` (--maps DIR) if not NULL; else ./maps
 * when it holds the generated maps (the source tree after make maps); else the cache
 * $XDG_CACHE_HOME/retro/maps (default $HOME/.cache/retro/maps). Any map of the suite's set
 * missing there is generated first, with progress on stderr, exactly as make maps would. Says
 * where on stderr. Returns 0, or prints "retro CMD: ..." and returns CLI_EBADINPUT. */
int cli_maps_dir(const char *cmd, const char *given, char *dir, size_t n);

#endif
