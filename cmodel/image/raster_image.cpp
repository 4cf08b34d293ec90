#include "image/raster_image.hpp"

#include <algorithm>

namespace cig {

std::int32_t majority_owner(std::int32_t* ids, int count) {
  // Ties go to the earlier polygon; the background (-1) loses ties.
  std::sort(ids, ids + count);
  std::int32_t best = -1;
  int best_count = 0;
  for (int a = 0; a < count;) {
    int b = a;
    while (b < count && ids[b] == ids[a]) ++b;
    if (b - a > best_count || (b - a == best_count && best == -1 && ids[a] >= 0)) {
      best = ids[a];
      best_count = b - a;
    }
    a = b;
  }
  return best;
}

}  // namespace cig
