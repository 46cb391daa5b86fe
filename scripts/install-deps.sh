#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian packages lutkit needs, only those missing. Idempotent; run as root (or with
# sudo available). Extra packages may be named as arguments.
#   scripts/install-deps.sh           everything: the build, the editor, the tests, benchmarks,
#                                     sanitizers, fuzzing and the checks (./test.sh, CI)
#   scripts/install-deps.sh --cli     only what building the CLI needs (./run.sh)
#   scripts/install-deps.sh --editor  the CLI's and Qt 6 for the editor (./run.sh editor)
#   scripts/install-deps.sh --web     what building and serving the browser edition needs
#                                     (./run.sh web: emscripten, CMake, python3)
set -euo pipefail
# The CLI and its image module: compiler, CMake, OpenImageIO, OpenColorIO, the native codecs,
# GLM, CLI11, ccache.
CLI_PACKAGES=(cmake make g++ pkg-config libopenimageio-dev libopenexr-dev libpng-dev zlib1g-dev libjpeg62-turbo-dev
  libisal-dev libopencolorio-dev libglm-dev libcli11-dev libfast-float-dev libfmt-dev ccache)
EDITOR_PACKAGES=(qt6-base-dev libqt6opengl6-dev)
WEB_PACKAGES=(cmake make emscripten ccache python3)
case "${1:-}" in
  --cli) shift; set -- "${CLI_PACKAGES[@]}" "$@"; ONLY=1 ;;
  --editor) shift; set -- "${CLI_PACKAGES[@]}" "${EDITOR_PACKAGES[@]}" "$@"; ONLY=1 ;;
  --web) shift; set -- "${WEB_PACKAGES[@]}" "$@"; ONLY=1 ;;
  *) ONLY=0 ;;
esac
# desktop-file-utils, libxml2-utils, shared-mime-info: tests/desktop checks the editor's desktop files.
# libopenexr-dev, libpng-dev, zlib1g-dev, libjpeg62-turbo-dev, libisal-dev: the native image codecs
# (formats/src/imageio).
# ccache: rebuilds (the four builds of ./test.sh, a fresh clone in CI) reuse unchanged objects.
# ffmpeg: an outside reader in the tests (its lut3d filter reads the .cube files lutkit writes).
# python3-numpy: bench/compare_numpy.sh's yardstick for lutkit match (a plain HM-MKL-HM in numpy),
# and with imagemagick and libtiff-tools the other readers of tests/robust/write_matrix.py (every
# image lutkit writes read back by oiiotool, ImageMagick, ffmpeg and libtiff, compared in numpy).
# openexr: OpenEXR's own tools (exrstdattr, exrmakepreview, exrmultiview) write the test files
# that carry every attribute type OpenEXR knows (tests/formats/test_image_plausibility.cpp).
# nasm: ISA-L's inflate assembly in lutkit.exe (docs/windows.md); zsh and fish: the completion
# tests run each shell's own completion (tests/cli/test_completion_names.cpp).
PACKAGES=(cmake make g++ pkg-config libopenimageio-dev openimageio-tools openexr libopenexr-dev libpng-dev
  zlib1g-dev libjpeg62-turbo-dev libisal-dev libopencolorio-dev
  opencolorio-tools qt6-base-dev libqt6opengl6-dev libglm-dev libgtest-dev libgmock-dev
  libcli11-dev libbenchmark-dev xvfb xauth clang clang-format libclang-rt-14-dev
  desktop-file-utils libxml2-utils shared-mime-info ccache ffmpeg python3-numpy
  imagemagick libtiff-tools libfast-float-dev libfmt-dev emscripten mingw-w64 nasm wine64 zsh fish chromium chromium-driver python3-selenium "$@")
if [ "$ONLY" = 1 ]; then
  PACKAGES=("$@")
fi
missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
