# Sourced by the shell scripts and tests that render the benchmark's six scenes outside it
# (scripts/study-replay.sh, tests/skipping_doc_counts.sh): their maps and poses, as
# bench/scenes.c sets them, said once for the shell.

# bench_scene_args NAME COURSE: retro render's MAP and camera options for scene NAME, the
# course's maps read from the folder COURSE; exit status 1 for an unknown NAME
bench_scene_args() {
  case $1 in
    alpine | islands | canyon) echo "maps/$1" ;;
    valley) echo "$2/valley -p 997.808716,559.177063 -z 230 -a 0" ;;
    island) echo "$2/island -p 147.436798,539.899414 -z 88 -a 0" ;;
    pyramids) echo "$2/pyramids -p 110.388893,887.813843 -z 164 -a 0" ;;
    *) return 1 ;;
  esac
}

# bench_scene_course NAME: whether scene NAME is one of the course's (read from ../shared)
bench_scene_course() {
  case $1 in valley | island | pyramids) return 0 ;; *) return 1 ;; esac
}
