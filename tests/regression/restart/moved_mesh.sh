#!/bin/bash
# moved_mesh.sh DIR GOOD_MESH DECK -- COMMAND...: writes a restart file of DECK on a copy of GOOD_MESH
# (COMMAND without its launcher, on one rank; Max Wall Time stops it after its first increment), moves
# one node of the copy (move_node.py), then runs COMMAND DECK --restart with it: the restart must be
# refused for another mesh (run_expect.sh checks the one line and the status).
set -u
dir=$1 good=$2 deck=$3
shift 4
contessa=${!#}  # the last word of COMMAND is contessa itself
name=$(basename "$deck" .xml)
args=(--quiet --set "Problem/Mesh/File Name=$dir/mesh.exo" --output-dir "$dir/out")
rm -rf "$dir" && mkdir -p "$dir" && cp "$good" "$dir/mesh.exo" || exit 1
"$contessa" "$deck" "${args[@]}" --set "Problem/Output/Checkpoint/Max Wall Time=0.001" > /dev/null
test -f "$dir/out/$name.restart" || { echo "no restart file written" >&2; exit 1; }
/usr/bin/python3 "$(dirname "$0")/move_node.py" "$dir/mesh.exo" || exit 1
"$@" "$deck" "${args[@]}" --restart "$dir/out/$name.restart"
