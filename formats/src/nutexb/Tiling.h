#pragma once
// The Tegra X1 block-linear tiling used by nutexb. Declared publicly in lut/formats/Nutexb.h
// (tests and fuzzers call it); this internal header only gathers the includes for formats/src.
#include "lut/formats/Nutexb.h"
