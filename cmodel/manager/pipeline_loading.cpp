#include "manager/pipeline_loading.hpp"

#include <algorithm>
#include <cmath>

namespace cig {

namespace {

// before[p]: the polygons of the list's subobjects before position p (p = 0..size).
std::vector<std::uint64_t> polygons_before(const PriorityList& list, const WorldDatabase& db) {
  std::vector<std::uint64_t> before(list.subobjects.size() + 1, 0);
  for (const PriorityEntry& e : list.objects)
    for (std::uint32_t p = e.first; p < e.first + e.count; ++p)
      before[p + 1] = db.objects[e.object].subobjects[list.subobjects[p]].face_normal.size();
  for (std::size_t p = 1; p < before.size(); ++p) before[p] += before[p - 1];
  return before;
}

// The subobject positions where the pipelines' lists start (cuts[0] = 0, cuts[N] = size).
std::vector<std::uint32_t> cut_positions(const PriorityList& list, const std::vector<std::uint64_t>& before,
                                         int pipelines, std::uint64_t& inside_groups) {
  std::vector<std::uint32_t> boundaries;  // group starts as subobject positions, and the end
  for (std::uint32_t g : list.group_first) boundaries.push_back(list.objects[g].first);
  boundaries.push_back(std::uint32_t(list.subobjects.size()));
  const double total = double(before.back()), share = total / pipelines;
  std::vector<std::uint32_t> cuts{0};
  for (int k = 1; k < pipelines; ++k) {
    const double target = share * k;
    // The subobject position nearest the target, and the group boundary nearest it.
    const auto at = std::lower_bound(before.begin(), before.end(), std::uint64_t(std::ceil(target)));
    std::uint32_t cut = std::uint32_t(at - before.begin());
    if (cut > 0 && target - double(before[cut - 1]) < double(before[cut]) - target) --cut;
    const auto g = std::min_element(boundaries.begin(), boundaries.end(), [&](std::uint32_t a, std::uint32_t b) {
      return std::fabs(double(before[a]) - target) < std::fabs(double(before[b]) - target);
    });
    if (std::fabs(double(before[*g]) - target) <= share / 8) cut = *g;
    else ++inside_groups;
    cuts.push_back(std::max(cut, cuts.back()));
  }
  cuts.push_back(std::uint32_t(list.subobjects.size()));
  return cuts;
}

// The entries' runs cut at [begin, end): a run's light points go with the piece holding its start;
// an entry of light points only (no subobjects) goes to the list whose slice holds its position.
PriorityList slice(const PriorityList& list, std::uint32_t begin, std::uint32_t end, bool last) {
  PriorityList out;
  for (const PriorityEntry& e : list.objects) {
    const bool start_inside = e.first >= begin && (e.first < end || (last && e.first == end));
    if (e.count == 0) {
      if (start_inside) out.objects.push_back({e.object, std::uint32_t(out.subobjects.size()), 0, e.lights});
      continue;
    }
    const std::uint32_t a = std::max(e.first, begin), b = std::min(e.first + e.count, end);
    if (a >= b) continue;
    out.objects.push_back({e.object, std::uint32_t(out.subobjects.size()), b - a, e.lights && start_inside});
    out.subobjects.insert(out.subobjects.end(), list.subobjects.begin() + a, list.subobjects.begin() + b);
  }
  return out;
}

}  // namespace

PipelineLoad load_pipelines(const PriorityList& list, const WorldDatabase& db, int pipelines) {
  PipelineLoad load;
  const std::vector<std::uint64_t> before = polygons_before(list, db);
  const std::vector<std::uint32_t> cuts = cut_positions(list, before, std::max(1, pipelines), load.cuts_inside_groups);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    load.lists.push_back(slice(list, cuts[k], cuts[k + 1], k + 2 == cuts.size()));
    load.polygons.push_back(before[cuts[k + 1]] - before[cuts[k]]);
  }
  return load;
}

double load_balance(const std::vector<std::uint64_t>& counts) {
  std::uint64_t most = 0, sum = 0;
  for (std::uint64_t c : counts) {
    most = std::max(most, c);
    sum += c;
  }
  return sum == 0 ? 1.0 : double(most) * double(counts.size()) / double(sum);
}

}  // namespace cig
