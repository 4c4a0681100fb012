#pragma once
// IES LM-63 photometric files (1986 style without a version line, LM-63-1995, -2002, -2019):
// keyword lines, TILT=NONE or TILT=INCLUDE (a separate tilt file is rejected), and the candela
// table of type C photometry. Type A and B photometry are rejected.
//
// Candela values are made absolute by the candela multiplier and the ballast factor. The 1995
// ballast-lamp factor / 2002 "future use" / 2019 file generation type field is read and ignored.
// Horizontal-angle symmetry (last angle 0, 90, 180 or 360) is expanded to the full circle:
// 90 mirrors the quadrant about the C90-C270 plane and then about C0-C180, 180 mirrors about C0-C180.

#include "core/photometry/goniometric_distribution.h"

namespace lucerna {

// Parses the text of an IES file; `label` (the file name) starts every error message:
// "label: line N: problem". Throws LuminaireFileError.
GoniometricDistribution parseIes(const std::string& text, const std::string& label);

}  // namespace lucerna
