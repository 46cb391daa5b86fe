# SPDX-License-Identifier: Apache-2.0
# Sourced by bench/match_halves.sh and bench/compare_numpy.sh: the outside programs that grade
# and measure for the match benchmarks. Needs $ROOT (the checkout) and $W (a scratch folder).

# The match tests' known grade as a 65^3 .cube (bench/grade_cube.py), written once into $W.
write_grade_cube() {
  python3 "$ROOT/bench/grade_cube.py" "$W/grade.cube"
}
# IN OUT: IN graded by ffmpeg's lut3d (tetrahedral) with that .cube, as an 8-bit RGB PNG.
graded() {
  ffmpeg -v error -y -i "$1" -vf "lut3d=file=$W/grade.cube:interp=tetrahedral" -pix_fmt rgb24 \
    -frames:v 1 -update 1 "$2"
}
# A B: idiff's mean absolute difference over every channel value, in 8-bit steps (idiff exits
# non-zero when the pictures differ, and prints no figures when they do not).
steps() {
  { idiff -a "$1" "$2" 2>/dev/null || true; } | awk '/Mean error/ {m = $4} END {printf "%.2f", m * 255}'
}
