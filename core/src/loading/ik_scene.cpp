#include "loading/ik_scene.hpp"

#include <sstream>

namespace springlab {

using json_reader::as_number;
using json_reader::between;
using json_reader::describe;
using json_reader::fail_at;
using json_reader::json;
using json_reader::ObjectReader;
using json_reader::positive;

namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

std::string degrees_text(double radians) {
  std::ostringstream s;
  s.precision(6);
  s << radians / kRadiansPerDegree;
  return s.str();
}

// "got 2 entries" for an array of the wrong size, else the usual description.
std::string got(const json& value) {
  return value.is_array() ? "got " + std::to_string(value.size()) + " entries" : describe(value);
}

}  // namespace

IkChain read_ik_chain(ObjectReader& r) {
  IkChain chain;
  const Vec3 base = r.vec3("base", Vec3::Zero());
  if (base.z() != 0.0)
    fail_at(r.where(), r.path("base") + "/2",
            "must be 0: the chain lies in the x-y plane, got " + json(base.z()).dump());
  chain.base = base.head<2>();

  const std::string links_allowed = "an array of 1 to " + std::to_string(kMaxIkLinks) +
                                    " link lengths in metres, each in (0, 1000]";
  const json* links = r.raw("links");
  if (!links) r.fail("links", "is required: " + links_allowed);
  if (!links->is_array() || links->empty() || links->size() > static_cast<std::size_t>(kMaxIkLinks))
    r.fail("links", "must be " + links_allowed + ", " + got(*links));
  const std::size_t n = links->size();
  for (std::size_t i = 0; i < n; ++i)
    chain.lengths.push_back(as_number((*links)[i], r.path("links") + "/" + std::to_string(i),
                                      r.where(), positive(1e3)));

  const std::string per_link = " per link (" + std::to_string(n) + ")";
  if (const json* limits = r.raw("limits")) {
    const std::string allowed = "an array of one limit" + per_link +
                                ", each [min, max] in degrees with -180 <= min < max <= 180, or "
                                "null for none";
    if (!limits->is_array() || limits->size() != n)
      r.fail("limits", "must be " + allowed + ", " + got(*limits));
    for (std::size_t i = 0; i < n; ++i) {
      const json& item = (*limits)[i];
      const std::string pointer = r.path("limits") + "/" + std::to_string(i);
      if (item.is_null()) {
        chain.limits.emplace_back();
        continue;
      }
      if (!item.is_array() || item.size() != 2)
        fail_at(r.where(), pointer,
                "must be [min, max] in degrees, or null for no limit, " + describe(item));
      const double lo = as_number(item[0], pointer + "/0", r.where(), between(-180.0, 180.0));
      const double hi = as_number(item[1], pointer + "/1", r.where(), between(-180.0, 180.0));
      if (!(lo < hi)) fail_at(r.where(), pointer, "must have min < max, got " + item.dump());
      chain.limits.push_back(JointLimit{lo * kRadiansPerDegree, hi * kRadiansPerDegree});
    }
  }

  // Without "angles" the chain starts straight along +x, each limited joint at the allowed angle
  // nearest 0. Given angles must already be allowed: a scene should not start in a pose that the
  // first iteration silently changes.
  chain.angles.assign(n, 0.0);
  if (const json* angles = r.raw("angles")) {
    const std::string allowed =
        "an array of one angle" + per_link + " in degrees, each in [-180, 180]";
    if (!angles->is_array() || angles->size() != n)
      r.fail("angles", "must be " + allowed + ", " + got(*angles));
    for (std::size_t i = 0; i < n; ++i) {
      const std::string pointer = r.path("angles") + "/" + std::to_string(i);
      const double theta =
          as_number((*angles)[i], pointer, r.where(), between(-180.0, 180.0)) * kRadiansPerDegree;
      const auto limit = chain.limit(static_cast<int>(i));
      if (limit && !(theta >= limit->min && theta <= limit->max))
        fail_at(r.where(), pointer,
                "must be within the joint's limits [" + degrees_text(limit->min) + ", " +
                    degrees_text(limit->max) + "] (\"limits\"), got " + (*angles)[i].dump());
      chain.angles[i] = theta;
    }
  } else {
    for (std::size_t i = 0; i < n; ++i)
      chain.angles[i] = clamp_angle(0.0, chain.limit(static_cast<int>(i)));
  }
  return chain;
}

}  // namespace springlab
