// The spectral CGATS (IT8) text files Debian's colord-data ships: the CIE colour-
// matching functions (cmf/*.cmf) and standard illuminants (illuminant/*.sp).
// Read here rather than with liblcms2 because the format used is small: keywords,
// BEGIN_DATA_FORMAT with fields SPEC_<nm>, and BEGIN_DATA with one row a set:
//
//   SPECTRAL_START_NM 360.0      (other keywords ignored)
//   BEGIN_DATA_FORMAT
//    SPEC_360 SPEC_365 ...
//   END_DATA_FORMAT
//   BEGIN_DATA
//    0.0001299 0.0002321 ...     (one row per set: x-bar, y-bar, z-bar for a .cmf)
//   END_DATA
#pragma once

#include "spectral/spectrum.h"

#include <string>
#include <vector>

namespace m3055::spectral {

// Every data row of `text` as a spectrum: on SPECTRAL_START_NM ... SPECTRAL_END_NM
// split evenly over the fields when the file gives both, else on the fields'
// SPEC_<nm> wavelengths, which must then be evenly spaced. Every row must hold as
// many finite numbers as there are fields, and there must be at least one row. Throws SpectralError
// "SOURCE: problem" (SOURCE: the file's name, as the message shows it).
std::vector<Spectrum> parse_cgats_spectra(const std::string& text, const std::string& source);

// Reads the file at `path` (bounded, regular files only) and parses it; a missing
// or unreadable file is one line naming it.
std::vector<Spectrum> read_cgats_spectra(const std::string& path);

}  // namespace m3055::spectral
