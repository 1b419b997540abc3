#pragma once
// A tiny built-in 5x7 pixel font for plot labels: digits, letters (lower case
// drawn as upper case), space and . - + ( ) [ ] / % : , _ =. Any other
// character is drawn as a hollow box.
#include <array>
#include <cstdint>

namespace unimap::eval {

class BitmapFont {
 public:
  static constexpr int kGlyphWidth = 5;   // pixels per glyph row
  static constexpr int kGlyphHeight = 7;  // rows per glyph
  static constexpr int kAdvance = 6;      // horizontal step per character (1 pixel gap)

  // The glyph of c: kGlyphHeight rows, top first; bit (kGlyphWidth - 1 - x)
  // of a row is set when pixel x (from the left) is inked.
  static const std::array<std::uint8_t, kGlyphHeight>& Glyph(char c);
};

}  // namespace unimap::eval
