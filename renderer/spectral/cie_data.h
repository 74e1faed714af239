// The CIE data the spectral lights use, read from Debian's colord-data
// (docs/spec.md#71-spectral-lights): the CIE 1931 2-degree colour-matching
// functions x-bar, y-bar, z-bar (360-830 nm, 5 nm) and the CIE standard
// illuminants A, B, C, D50, D55, D65, D93, E, F1-F12 (300-830 nm, 5 nm).
// Each file is read once per process and kept.
#pragma once

#include "spectral/spectrum.h"

#include <string>
#include <vector>

namespace m3055::spectral {

// Where the files are: $M3055_COLORD_DIR when set (tests point it at a copy or
// at an empty folder), else /usr/share/colord.
std::string colord_dir();

struct Observer {
    Spectrum x, y, z;  // on one grid
};

// CIE 1931 2-degree standard observer: COLORD_DIR/cmf/CIE1931-2deg-XYZ.cmf.
// Throws SpectralError naming the file when it is missing or malformed.
const Observer& cie1931_observer();

// The illuminant names the scene format accepts, as colord-data names its files.
const std::vector<std::string>& illuminant_names();
// COLORD_DIR/illuminant/CIE-NAME.sp (NAME one of illuminant_names()).
const Spectrum& cie_illuminant(const std::string& name);

}  // namespace m3055::spectral
