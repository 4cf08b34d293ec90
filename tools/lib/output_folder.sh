# shellcheck shell=bash
# Sourced by the tools that write into a folder the user names (tools/hls_export.sh,
# tools/synth_report.sh), so that they never delete or overwrite what they did not write:
#   of_check_place OUT REPO [build]    refuses (exit 2) a place no tool may write to: an existing
#                                      non-folder, the source tree (with "build": except its
#                                      build*/ and out/ folders), a parent of the source tree,
#                                      $HOME and its parents. Symlinks and .. are resolved first.
#   of_check_claim OUT MARKER          OUT is missing, empty, or holds MARKER (a folder the tool
#                                      wrote before); anything else is refused.
#   of_manifest OUT MARKER             the files MARKER lists (written by the tool), one a line.
#   of_check_written OUT MARKER REPO FILE...
#                                      each FILE that exists in OUT is listed in OUT's MARKER, or
#                                      OUT lies in a build folder of REPO (generated files only).
#   of_check_install STAGING OUT MARKER
#                                      of_install's checks alone (run them all before any write).
#   of_install STAGING OUT MARKER HEADER
#                                      moves STAGING's files into OUT: the files of OUT's old
#                                      manifest are replaced or removed, every other file stays.
# Set of_prog (the name messages lead with) before calling them. Markers are text: a first line
# "NAME 1" (NAME: the marker's file name without its dot), then "key value" lines, and one
# "file PATH" line per file written (paths relative to the folder).

of_prog=${of_prog:-$(basename -- "$0")}
of_cleanup=()
of_run_cleanup() {
  local p
  for p in "${of_cleanup[@]}"; do rm -rf -- "$p"; done
}
trap of_run_cleanup EXIT

of_fail() {
  echo "$of_prog: $*" >&2
  exit 2
}

# The absolute path with symlinks and .. resolved (missing components kept as written).
of_resolve() { realpath -m -- "$1"; }

# of_within A B: A is B or lies inside B (both resolved).
of_within() {
  [ "$1" = "$2" ] || [ "$2" = / ] || case $1 in "$2"/*) true ;; *) false ;; esac
}

# The path as the user wrote it, and what it resolves to when that differs.
of_shown() {
  local real
  real=$(of_resolve "$1")
  if [ "$real" = "$1" ]; then echo "$1"; else echo "$1 (= $real)"; fi
}

of_check_place() {
  local out=$1 repo=$2 mode=${3:-} real home shown
  real=$(of_resolve "$out")
  shown=$(of_shown "$out")
  if [ -e "$real" ] && [ ! -d "$real" ]; then
    of_fail "$shown: exists and is not a folder; name a new or empty folder"
  fi
  if [ "$real" = "$repo" ]; then
    of_fail "$shown: is the source tree's root; name a new or empty folder outside it"
  fi
  if of_within "$repo" "$real"; then
    of_fail "$shown: is a parent of the source tree $repo; name a new or empty folder of its own"
  fi
  if of_within "$real" "$repo"; then
    local rel=${real#"$repo"/}
    case $mode/$rel in
      build/build* | build/out | build/out/*) ;;
      build/*) of_fail "$shown: lies inside the source tree $repo; write outside it, or under its build*/ or out/" ;;
      *) of_fail "$shown: lies inside the source tree $repo; write outside it, into a new or empty folder" ;;
    esac
  fi
  if [ -n "${HOME:-}" ]; then
    home=$(of_resolve "$HOME")
    if [ "$real" = "$home" ]; then
      of_fail "$shown: is your home folder; name a new or empty folder of its own"
    elif of_within "$home" "$real"; then
      of_fail "$shown: is a parent of your home folder $home; name a new or empty folder of its own"
    fi
  fi
}

# Whether DIR/MARKER is a marker of that name (its first line).
of_has_marker() {
  [ -f "$1/$2" ] && [ ! -L "$1/$2" ] && [ "$(head -n 1 -- "$1/$2")" = "${2#.} 1" ]
}

of_check_claim() {
  local out=$1 marker=$2 real
  real=$(of_resolve "$out")
  [ -e "$real" ] || return 0
  local entries
  entries=$(ls -A -- "$real") || of_fail "$(of_shown "$out"): cannot be read"
  [ -n "$entries" ] || return 0
  of_has_marker "$real" "$marker" && return 0
  of_fail "$(of_shown "$out"): is not empty and holds no $marker marker, so it is no folder this script" \
    "wrote (it never replaces what it did not write); name a new or empty folder"
}

# The value of "KEY value" in a marker ("" when absent).
of_marker_value() { sed -n "s/^$3 //p" -- "$1/$2" | head -n 1; }

of_manifest() {
  local dir=$1 marker=$2 n=0 line path
  of_has_marker "$dir" "$marker" || return 0
  while IFS= read -r line; do
    n=$((n + 1))
    case $line in file\ *) ;; *) continue ;; esac
    path=${line#file }
    # Only plain relative paths below the folder: a damaged marker must not name anything else.
    if ! [[ $path =~ ^[A-Za-z0-9_.+-]+(/[A-Za-z0-9_.+-]+)*$ ]] || [[ /$path/ == */../* ]] || [[ /$path/ == */./* ]]; then
      of_fail "$dir/$marker: line $n: '$path' is not a path inside the folder (a damaged marker; remove the" \
        "folder yourself or name a new one)"
    fi
    echo "$path"
  done <"$dir/$marker"
}

# Every path in the list (stdin) lies inside DIR once resolved: no symlinked folder leads out.
of_check_inside() {
  local dir=$1 path
  while IFS= read -r path; do
    [ -n "$path" ] || continue
    of_within "$(of_resolve "$dir/$(dirname -- "$path")")" "$dir" ||
      of_fail "$dir/$path: leads out of $dir through a symbolic link; name a new or empty folder"
  done
}

# Whether DIR lies in a build folder of REPO: a CMakeCache.txt above it names REPO as its source.
of_in_build_tree() {
  local dir=$1 repo=$2
  while :; do
    if [ -f "$dir/CMakeCache.txt" ] && grep -qxF "CMAKE_HOME_DIRECTORY:INTERNAL=$repo" "$dir/CMakeCache.txt"; then
      return 0
    fi
    [ "$dir" != / ] || return 1
    dir=$(dirname -- "$dir")
  done
}

of_check_written() {
  local dir=$1 marker=$2 repo=$3 listed path
  shift 3
  dir=$(of_resolve "$dir")
  [ -d "$dir" ] || return 0
  ! of_in_build_tree "$dir" "$repo" || return 0
  listed=$(of_manifest "$dir" "$marker")
  for path in "$@"; do
    if { [ -e "$dir/$path" ] || [ -L "$dir/$path" ]; } && ! grep -qxF -- "$path" <<<"$listed"; then
      of_fail "$dir/$path: exists and is not listed in $dir/$marker (this script did not write it); move it" \
        "away or name a new or empty folder"
    fi
  done
}

# Writes DIR/MARKER (HEADER's lines, then one "file" line per path of LIST) through a temporary
# file, so that the marker is always whole.
of_write_marker() {
  local dir=$1 marker=$2 header=$3 list=$4 tmp
  tmp=$(mktemp "$dir/.cig-marker.XXXXXX")
  chmod "$(printf '%o' $((0666 & ~0$(umask))))" "$tmp"  # as any file written (mktemp makes it private)
  {
    printf '%s\n' "$header"
    # shellcheck disable=SC2086  # one path a word (paths hold no blanks: of_manifest)
    [ -z "$list" ] || printf 'file %s\n' $list
  } >"$tmp"
  mv -f -- "$tmp" "$dir/$marker"
}

# The checks of of_install, to run for every folder before anything is written: a file STAGING
# brings that exists in OUT but is not in its manifest, or a path leading out of OUT, is refused.
of_check_install() {
  local staging=$1 out=$2 marker=$3 dest old new path
  dest=$(of_resolve "$out")
  old=$(of_manifest "$dest" "$marker" | sort -u)
  new=$(cd "$staging" && find . -type f | sed 's|^\./||' | sort)
  for path in $new; do
    if { [ -e "$dest/$path" ] || [ -L "$dest/$path" ]; } && ! grep -qxF -- "$path" <<<"$old"; then
      of_fail "$dest/$path: exists and is not part of what this script wrote there before; move it away or" \
        "name a new or empty folder"
    fi
    if [ -d "$dest/$path" ] && [ ! -L "$dest/$path" ]; then
      of_fail "$dest/$path: is a folder where the bundle writes a file; move it away or name a new or empty folder"
    fi
  done
  printf '%s\n' "$old" "$new" | of_check_inside "$dest"
}

of_install() {
  local staging=$1 out=$2 marker=$3 header=$4 dest old new path incoming
  of_check_install "$staging" "$out" "$marker"
  dest=$(of_resolve "$out")
  old=$(of_manifest "$dest" "$marker" | sort -u)
  new=$(cd "$staging" && find . -type f | sed 's|^\./||' | sort)
  mkdir -p -- "$dest"
  # The new files first go next to the old ones (same file system), so that a failure while they
  # are copied leaves the old bundle whole; then each is moved in (a rename).
  incoming=$(mktemp -d "$dest/.cig-incoming.XXXXXX")
  of_cleanup+=("$incoming")
  cp -R -- "$staging/." "$incoming/"
  # Meanwhile the marker lists old and new files, so that an interrupted run can be repeated.
  of_write_marker "$dest" "$marker" "$header" "$(printf '%s\n' "$old" "$new" | sort -u)"
  for path in $old; do
    grep -qxF -- "$path" <<<"$new" && continue
    if [ -f "$dest/$path" ] || [ -L "$dest/$path" ]; then rm -f -- "$dest/$path"; fi
    (cd "$dest" && rmdir -p --ignore-fail-on-non-empty -- "$(dirname -- "$path")" 2>/dev/null) || true
  done
  for path in $new; do
    mkdir -p -- "$dest/$(dirname -- "$path")"
    mv -f -- "$incoming/$path" "$dest/$path"
  done
  rm -rf -- "$incoming"
  of_write_marker "$dest" "$marker" "$header" "$new"
}
