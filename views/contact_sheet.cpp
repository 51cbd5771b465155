// contactSheet: tiles in a grid with their labels, for looking at several views at once.
#include <algorithm>
#include <cstddef>

#include "core/error.h"
#include "views/canvas.h"
#include "views/palette.h"
#include "views/type.h"
#include "views/views.h"

namespace uvtk::views {

namespace {

constexpr int kSheetPadding = 8;  // around and between cells
constexpr int kLabelGap = 4;      // between a tile and its label
constexpr double kLabelSize = 15;

// A tile's pixel as RGB: grey (and grey with alpha) spread to three channels, RGBA without alpha.
Vec3 tileColour(const Image& tile, int x, int row) {
  if (tile.channels < 3) return Vec3::Constant(tile.at(x, row, 0));
  return {tile.at(x, row, 0), tile.at(x, row, 1), tile.at(x, row, 2)};
}

}  // namespace

Image contactSheet(const std::vector<std::pair<std::string, Image>>& tiles, int columns) {
  if (tiles.empty()) throw UsageError("contact sheet: expected at least one tile, found none");
  if (columns < 1) throw UsageError("contact sheet: expected at least one column, found " + std::to_string(columns));
  const std::size_t perRow = std::size_t(columns), rows = (tiles.size() + perRow - 1) / perRow;
  // Each column as wide as its widest tile or label, each row as high as its highest tile plus a label.
  std::vector<int> columnWidth(std::min(perRow, tiles.size()), 0), rowHeight(rows, 0);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const auto& [label, tile] = tiles[k];
    UVTK_CHECK(tile.channels >= 1);
    int& width = columnWidth[k % perRow];
    const TextMetrics text = measureText(label, kLabelSize);
    width = std::max({width, tile.width, text.width});
    int& height = rowHeight[k / perRow];
    height = std::max(height, tile.height + kLabelGap + text.height);
  }
  auto offsets = [](const std::vector<int>& sizes) {  // where each cell starts
    std::vector<int> start(1, kSheetPadding);
    for (int size : sizes) start.push_back(start.back() + size + kSheetPadding);
    return start;
  };
  const std::vector<int> x0 = offsets(columnWidth), y0 = offsets(rowHeight);

  Image sheet(x0.back(), y0.back(), 3);
  fillRect(sheet, 0, 0, sheet.width, sheet.height, kPanelColour);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const auto& [label, tile] = tiles[k];
    const int left = x0[k % perRow], top = y0[k / perRow];
    for (int row = 0; row < tile.height; ++row)
      for (int x = 0; x < tile.width; ++x) setPixel(sheet, left + x, top + row, tileColour(tile, x, row));
    drawText(sheet, left, top + tile.height + kLabelGap, label, kLabelSize, kTextColour);
  }
  return sheet;
}

}  // namespace uvtk::views
