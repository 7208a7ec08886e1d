#!/bin/sh
# Writes retro.pc on stdout: pkg-config's description of the installed library.
# usage: make-pc.sh PREFIX VERSION "PKG-CONFIG PACKAGES" "OTHER LINK FLAGS"
# A shared link needs only -lretro (libretro.so names its libraries); a static one
# (pkg-config --static) adds the packages (Requires.private) and OpenMP and libm
# (Libs.private).
set -eu
. "$(dirname "$0")/usage.sh"
script_args 4 4 "$@"
cat <<PC
prefix=$1
libdir=\${prefix}/lib
includedir=\${prefix}/include

Name: retro
Description: voxel-space terrain render kernels, pixel-identical to one frame definition
Version: $2
Requires.private: $3
Cflags: -I\${includedir}/retro
Libs: -L\${libdir} -lretro
Libs.private: $4
PC
