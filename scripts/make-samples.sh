#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates samples/sample_scene.{exr,png} and samples/sample_grade.cube from
# samples/tools/make_samples.cpp (deterministic).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" --target make_samples -j"$(nproc)" >/dev/null
"$root/build/bin/make_samples" "$root/samples"
ls -l "$root/samples"/sample_*
