#pragma once
// An RGB raster with the few drawing operations the plots need.
#include <cstdint>
#include <string>
#include <vector>

namespace unimap::eval {

class PlotCanvas {
 public:
  // 8-bit sRGB colour.
  struct Color {
    std::uint8_t r = 0;  // red
    std::uint8_t g = 0;  // green
    std::uint8_t b = 0;  // blue
    bool operator==(const Color& o) const { return r == o.r && g == o.g && b == o.b; }
  };
  // Pixel rectangle; x, y = top-left corner, y grows downwards.
  struct Rect {
    int x = 0;       // left column
    int y = 0;       // top row
    int width = 0;   // columns
    int height = 0;  // rows
    bool Contains(int px, int py) const { return px >= x && px < x + width && py >= y && py < y + height; }
  };

  // A width x height canvas filled with background; throws InputError for a
  // non-positive or absurd (> 16384) size.
  PlotCanvas(int width, int height, Color background);

  int width() const { return width_; }
  int height() const { return height_; }
  // Row-major RGB bytes, 3 per pixel, top row first.
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }
  // Colour at (x, y); requires a pixel inside the canvas.
  Color At(int x, int y) const;

  // Sets one pixel; pixels outside the canvas (or outside clip, if given) are ignored.
  void SetPixel(int x, int y, Color color, const Rect* clip = nullptr);
  // Fills the rectangle (clipped to the canvas).
  void FillRect(const Rect& rect, Color color);
  // One-pixel outline of the rectangle.
  void StrokeRect(const Rect& rect, Color color);
  // Straight line between pixel-space points, thickness pixels wide, clipped
  // to clip (or the canvas). Non-finite end points draw nothing.
  void DrawLine(double x0, double y0, double x1, double y1, Color color, int thickness,
                const Rect* clip = nullptr);
  // Text with BitmapFont, top-left corner at (x, y), each font pixel scale x scale.
  void DrawText(int x, int y, const std::string& text, Color color, int scale);

  // Size of DrawText's output in pixels.
  static int TextWidth(const std::string& text, int scale);
  static int TextHeight(int scale);

 private:
  int width_;
  int height_;
  std::vector<std::uint8_t> rgb_;
};

}  // namespace unimap::eval
