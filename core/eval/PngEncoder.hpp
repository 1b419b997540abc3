#pragma once
// PNG encoding of a PlotCanvas (stb_image_write from Debian's libstb-dev).
#include <string>

#include "eval/PlotCanvas.hpp"

namespace unimap::eval {

// The PNG file bytes of the canvas (8-bit RGB). Throws unimap::Error when
// the encoder fails.
std::string EncodePng(const PlotCanvas& canvas);

}  // namespace unimap::eval
