#include "report/crop_regions.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "penumbra/error.hpp"

namespace penumbra {

namespace {

// Window sums of a per-pixel score through a summed-area table.
class WindowSums {
 public:
  WindowSums(int width, int height, const std::function<double(int, int)>& score)
      : width_(width), sums_(static_cast<std::size_t>(width + 1) * (height + 1), 0.0) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        at(x + 1, y + 1) = score(x, y) + at(x, y + 1) + at(x + 1, y) - at(x, y);
      }
    }
  }
  [[nodiscard]] double sum(int x, int y, int w, int h) const {
    return at(x + w, y + h) - at(x, y + h) - at(x + w, y) + at(x, y);
  }

 private:
  double& at(int x, int y) { return sums_[static_cast<std::size_t>(y) * (width_ + 1) + x]; }
  [[nodiscard]] double at(int x, int y) const {
    return sums_[static_cast<std::size_t>(y) * (width_ + 1) + x];
  }
  int width_;
  std::vector<double> sums_;
};

bool overlaps(const CropRegion& a, int x, int y, int w, int h) {
  return x < a.x + a.width && a.x < x + w && y < a.y + a.height && a.y < y + h;
}

}  // namespace

std::vector<CropRegion> choose_crop_regions(const Image& reference,
                                            const std::vector<const Image*>& techniques, int width,
                                            int height) {
  const int w = reference.width, h = reference.height;
  if (width < 1 || height < 1 || width > w || height > h) {
    throw RuntimeError("crop window does not fit the image");
  }
  for (const Image* t : techniques) {
    if (t->width != w || t->height != h) throw RuntimeError("images to crop differ in size");
  }
  const auto compared = [&](int x, int y) {
    if (reference.pixel(x, y)[3] < 0.5f) return false;
    return std::all_of(techniques.begin(), techniques.end(),
                       [&](const Image* t) { return t->pixel(x, y)[3] >= 0.5f; });
  };
  const auto value = [&](int x, int y) { return reference.pixel(x, y)[0]; };
  // The reference's slope at a compared pixel, from neighbours that are
  // compared too (a silhouette against the background is no shadow edge).
  const auto slope = [&](int x, int y) {
    float s = 0.0f;
    if (x > 0 && x + 1 < w && compared(x - 1, y) && compared(x + 1, y)) {
      s = std::max(s, std::abs(value(x + 1, y) - value(x - 1, y)) / 2.0f);
    }
    if (y > 0 && y + 1 < h && compared(x, y - 1) && compared(x, y + 1)) {
      s = std::max(s, std::abs(value(x, y + 1) - value(x, y - 1)) / 2.0f);
    }
    return s;
  };
  const WindowSums error(w, h, [&](int x, int y) {
    if (!compared(x, y)) return 0.0;
    double sum = 0.0;
    for (const Image* t : techniques) sum += std::abs(double(t->pixel(x, y)[0]) - value(x, y));
    return sum;
  });
  const WindowSums sharp(w, h, [&](int x, int y) {
    return compared(x, y) && slope(x, y) >= kSharpEdgeSlope ? 1.0 : 0.0;
  });
  const WindowSums wide(w, h, [&](int x, int y) {
    return compared(x, y) && value(x, y) > kPenumbraLow && value(x, y) < kPenumbraHigh &&
                   slope(x, y) < kSharpEdgeSlope
               ? 1.0
               : 0.0;
  });

  std::vector<CropRegion> regions = {
      {"largest-error", "Largest error",
       "the most |technique - reference|, summed over every technique", 0, 0, 0, 0, 0.0},
      {"contact-shadow", "Contact shadow",
       "the most pixels where the reference changes by 0.25 or more per pixel (a penumbra under "
       "4 pixels wide)",
       0, 0, 0, 0, 0.0},
      {"wide-penumbra", "Wide penumbra",
       "the most pixels where the reference is between 0.1 and 0.9 and changes by less than 0.25 "
       "per pixel",
       0, 0, 0, 0, 0.0},
  };
  const WindowSums* scores[] = {&error, &sharp, &wide};
  for (std::size_t i = 0; i < regions.size(); ++i) {
    double best = -1.0;
    for (int y = 0; y + height <= h; ++y) {
      for (int x = 0; x + width <= w; ++x) {
        const bool free = std::none_of(regions.begin(), regions.begin() + i, [&](const auto& r) {
          return overlaps(r, x, y, width, height);
        });
        if (!free) continue;
        const double s = scores[i]->sum(x, y, width, height);
        if (s > best) {
          best = s;
          regions[i].x = x, regions[i].y = y;
        }
      }
    }
    regions[i].width = width, regions[i].height = height;
    regions[i].score = std::max(best, 0.0);
  }
  return regions;
}

Image crop_nearest(const Image& image, const CropRegion& region, int scale) {
  if (region.x < 0 || region.y < 0 || region.x + region.width > image.width ||
      region.y + region.height > image.height || scale < 1) {
    throw RuntimeError("crop region outside the image");
  }
  Image out(region.width * scale, region.height * scale);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const float* p = image.pixel(region.x + x / scale, region.y + y / scale);
      std::copy(p, p + 4, out.pixel(x, y));
    }
  }
  return out;
}

}  // namespace penumbra
