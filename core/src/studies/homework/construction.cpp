// The constructor, Rope(start, end, num_nodes, node_mass, k, pinned_nodes), checked on every rope
// the checks use: two shown (the identification's rope and a slanted one pinned at both ends), the
// probes' small ropes quietly (a line only where one is wrong). What is wrong is named where it
// is one of the usual slips: nothing built yet, i / num_nodes for i / (num_nodes - 1), the rope
// laid from end to start, integer division, the pins left out or set before the masses exist, a
// spring to a mass the rope does not hold, a spring twice.
#include <algorithm>
#include <cmath>

#include "parts.hpp"

namespace springlab::homework {

namespace {

std::string request_text(const RopeRequest& r) {
  std::string pins;
  for (int p : r.pinned) pins += (pins.empty() ? "" : ", ") + std::to_string(p);
  return "Rope(" + vec(r.start) + ", " + vec(r.end) + ", " + std::to_string(r.nodes) + ", " +
         num(r.node_mass) + ", " + num(r.k) + ", {" + pins + "})";
}

std::string list_text(const std::vector<int>& list) {
  std::string t;
  for (int p : list) t += (t.empty() ? "" : ", ") + std::to_string(p);
  return "{" + t + "}";
}

// Where mass i is due, and where the usual slips put it.
Vec2 due(const RopeRequest& r, double fraction) {
  return r.start + (r.end - r.start) * fraction;
}

struct Layout {
  const char* key;
  const char* says;  // the sentence, with the mass's index and the two places
  double (*fraction)(int i, int n);
};

const Layout kLayouts[] = {
    {"spacing-n",
     N_("mass %d is at %s, not at %s: the masses are spaced by i / num_nodes, so the last falls "
        "short of end (mass i goes "
        "at start + i / (num_nodes - 1) (end - start))"),
     [](int i, int n) { return static_cast<double>(i) / n; }},
    {"reversed",
     N_("mass %d is at %s, not at %s: the rope is laid from end to start (mass 0 goes at start, "
        "mass num_nodes - 1 at end)"),
     [](int i, int n) { return 1.0 - static_cast<double>(i) / (n - 1); }},
    {"integer-division",
     N_("mass %d is at %s, not at %s: i / (num_nodes - 1) is divided as integers, 0 for every mass "
        "but the last (divide "
        "as double: (double)i / (num_nodes - 1))"),
     // The student's mistake, on purpose:
     // NOLINTNEXTLINE(bugprone-integer-division)
     [](int i, int n) { return static_cast<double>(i / (n - 1)); }},
    {"all-at-start",
     N_("mass %d is at %s, not at %s: every mass is at start (each must be moved along the rope)"),
     [](int, int) { return 0.0; }},
};

// The largest distance of any mass (position, start_position, last_position) from where a layout
// puts it.
double off_layout(const RopeRequest& r, const BuiltRope& rope, double (*fraction)(int, int),
                  int* worst = nullptr) {
  double off = 0.0;
  const int n = static_cast<int>(rope.masses.size());
  for (int i = 0; i < n; ++i) {
    const Vec2 at = due(r, fraction(i, n));
    const BuiltMass& m = rope.masses[i];
    const double d =
        std::max({(m.state.x - at).norm(), (m.start - at).norm(), (m.state.x_last - at).norm()});
    if (!(d <= off)) {
      off = d;
      if (worst) *worst = i;
    }
  }
  return off;
}

double exact_fraction(int i, int n) {
  return n > 1 ? static_cast<double>(i) / (n - 1) : 0.0;
}

// Positions: exact to double's rounding, or to float's (a fraction computed in float), or a slip.
bool check_positions(const RopeRequest& r, const BuiltRope& rope, const std::string& asked,
                     bool shown, CheckSection& section) {
  const double length = (r.end - r.start).norm();
  const double double_tol = 1e-12 * std::max(1.0, length + r.start.norm());
  const double float_tol = 4.0 * kFloatRounding * (r.start.norm() + r.end.norm() + length);
  int worst = 0;
  const double off = off_layout(r, rope, exact_fraction, &worst);
  const int n = static_cast<int>(rope.masses.size());
  const std::string masses = format_text(tr("%d masses of %s kg, evenly spaced from start to end"),
                                         n, num(r.node_mass).c_str());
  if (off <= double_tol) {
    if (shown) pass(section, "positions", asked + masses);
    return true;
  }
  if (off <= float_tol) {
    if (shown)
      pass(section, "positions",
           asked + masses +
               format_text(tr(" (to float's rounding, %s m: the spacing is computed in float)"),
                           num(off).c_str()));
    return true;
  }
  const Vec2 at = rope.masses[worst].state.x, want = due(r, exact_fraction(worst, n));
  for (const Layout& layout : kLayouts) {
    if (off_layout(r, rope, layout.fraction) <= float_tol) {
      const auto [got, due_text] = apart(at, want);
      fail(section, layout.key,
           asked + format_text(tr(layout.says), worst, got.c_str(), due_text.c_str()));
      return false;
    }
  }
  const BuiltMass& m = rope.masses[worst];
  const auto [got, due_text] = apart(m.state.x, want);
  if ((m.state.x - want).norm() <= float_tol)
    fail(section, "start-position",
         asked + format_text(tr("mass %d is at %s, but its start_position is %s and its "
                                "last_position %s: make each mass "
                                "with new Mass(position, node_mass, false), which sets all three"),
                             worst, vec(m.state.x).c_str(), vec(m.start).c_str(),
                             vec(m.state.x_last).c_str()));
  else
    fail(section, "positions",
         asked + format_text(tr("mass %d is at %s, not at %s (mass i goes at start + i / "
                                "(num_nodes - 1) (end - start))"),
                             worst, got.c_str(), due_text.c_str()));
  return false;
}

bool check_pins(const RopeRequest& r, const BuiltRope& rope, const std::string& asked, bool shown,
                CheckSection& section) {
  std::vector<int> pinned;
  for (int i = 0; i < static_cast<int>(rope.masses.size()); ++i)
    if (rope.masses[i].pinned) pinned.push_back(i);
  if (pinned == r.pinned) {
    if (shown) pass(section, "pins", asked + tr("pinned exactly the masses pinned_nodes names"));
    return true;
  }
  if (pinned.empty())
    fail(section, "pins-none",
         asked + format_text(tr("no mass is pinned, where pinned_nodes names %s: set "
                                "masses[i]->pinned = true for each i "
                                "in pinned_nodes (the skeleton's loop, still commented out?)"),
                             list_text(r.pinned).c_str()));
  else
    fail(section, "pins",
         asked + format_text(tr("pinned masses %s, where pinned_nodes names %s"),
                             list_text(pinned).c_str(), list_text(r.pinned).c_str()));
  return false;
}

bool check_springs(const RopeRequest& r, const BuiltRope& rope, const std::string& asked,
                   bool shown, CheckSection& section) {
  const int n = static_cast<int>(rope.masses.size());
  const double spacing = (r.end - r.start).norm() / (r.nodes - 1);
  const double float_tol =
      8.0 * kFloatRounding * (r.start.norm() + r.end.norm() + spacing * (r.nodes - 1));
  std::vector<int> joined(n, 0);
  auto wrong = [&](const char* key, const std::string& text) {
    fail(section, key, asked + text);
    return false;
  };
  for (int j = 0; j < static_cast<int>(rope.springs.size()); ++j) {
    const BuiltSpring& s = rope.springs[j];
    if (s.m1 == BuiltSpring::kNoMass || s.m2 == BuiltSpring::kNoMass)
      return wrong(
          "spring-null",
          format_text(tr("spring %d is a null pointer or joins one: each spring joins two of the "
                         "rope's masses, new Spring(masses[i], masses[i + 1], k)"),
                      j));
    if (s.m1 == BuiltSpring::kNotInRope || s.m2 == BuiltSpring::kNotInRope)
      return wrong(
          "spring-not-in-rope",
          format_text(
              tr("spring %d joins a mass that is not in masses (a Mass made for the spring, not "
                 "the one "
                 "pushed into masses): join the rope's own masses, masses[i] and masses[i + 1]"),
              j));
    const int lo = std::min(s.m1, s.m2), hi = std::max(s.m1, s.m2);
    if (hi != lo + 1 || hi >= n)
      return wrong("spring-not-neighbours",
                   format_text(tr("spring %d joins masses %d and %d, which are not neighbours"), j,
                               s.m1, s.m2));
    ++joined[lo];
    if (!(std::abs(s.k - r.k) <= 1e-6 * r.k))
      return wrong("spring-k", format_text(tr("spring %d's k is %s, not k = %s"), j,
                                           num(s.k).c_str(), num(r.k).c_str()));
    // Its rest length is its masses' distance as built (the Spring's constructor takes it so);
    // where the masses are misplaced, that is the positions' mistake, told above.
    const double distance = (rope.masses[hi].state.x - rope.masses[lo].state.x).norm();
    if (!(std::abs(s.rest - distance) <= float_tol + 1e-12 * spacing))
      return wrong("rest-length", format_text(tr("spring %d-%d's rest length is %s m, not the "
                                                 "distance of its masses, %s m (a Spring takes "
                                                 "its rest length from its masses' positions when "
                                                 "it is made: make it after the masses "
                                                 "are in place)"),
                                              lo, hi, num(s.rest).c_str(), num(distance).c_str()));
  }
  for (int i = 0; i + 1 < n; ++i) {
    if (joined[i] == 0)
      return wrong("spring-missing",
                   format_text(tr("no spring between masses %d and %d"), i, i + 1));
    if (joined[i] > 1)
      return wrong("spring-duplicated",
                   format_text(tr("%d springs between masses %d and %d, where there must be one "
                                  "(is each spring made twice?)"),
                               joined[i], i, i + 1));
  }
  if (shown)
    pass(
        section, "springs",
        asked + format_text(
                    tr("%d springs, one between each pair of neighbours, k = %s, rest length %s m"),
                    static_cast<int>(rope.springs.size()), num(r.k).c_str(), num(spacing).c_str()));
  return true;
}

// Returns whether the rope is built right; a line for each thing checked where `shown`, else
// only for what is wrong.
bool check_built(const RopeRequest& r, const BuiltRope& rope, bool shown, CheckSection& section) {
  const std::string asked = request_text(r) + ": ";
  const int n = static_cast<int>(rope.masses.size());
  if (n == 0 && rope.springs.empty()) {
    fail(section, "nothing-built",
         asked + tr("nothing built yet: the constructor makes no masses and no springs. Start "
                    "there (Part 1): num_nodes "
                    "masses from start to end (new Mass(position, node_mass, false)), a Spring "
                    "between each pair of "
                    "neighbours, then the pins"));
    return false;
  }
  if (n != r.nodes) {
    const char* hint =
        n == r.nodes - 1   ? N_(" (one short: does the loop stop before the last mass?)")
        : n == r.nodes + 1 ? N_(" (one too many: does the loop run to i <= num_nodes?)")
                           : "";
    fail(section, "mass-count",
         asked + format_text(tr("%d masses, where num_nodes = %d"), n, r.nodes) +
             (*hint ? tr(hint) : ""));
    return false;
  }
  bool ok = check_positions(r, rope, asked, shown, section);
  for (int i = 0; i < n; ++i)
    if (!(std::abs(rope.masses[i].mass - r.node_mass) <= 1e-7 * r.node_mass)) {
      fail(section, "node-mass",
           asked + format_text(tr("mass %d is %s kg, not node_mass = %s kg"), i,
                               num(rope.masses[i].mass).c_str(), num(r.node_mass).c_str()));
      ok = false;
      break;
    }
  ok = check_pins(r, rope, asked, shown, section) && ok;
  ok = check_springs(r, rope, asked, shown, section) && ok;
  return ok;
}

}  // namespace

bool check_construction(RopeCode& code, CheckSection& section) {
  const std::vector<RopeRequest> ropes = every_rope();
  for (size_t i = 0; i < ropes.size(); ++i) {
    const RopeRequest& r = ropes[i];
    BuiltRope rope;
    try {
      rope = code.build(r);
    } catch (const CodeFailure& e) {
      // A constructor that fails only when asked for pins sets them before its masses exist.
      if (!r.pinned.empty()) {
        RopeRequest unpinned = r;
        unpinned.pinned.clear();
        bool builds = false;
        try {
          code.build(unpinned);
          builds = true;
        } catch (const CodeFailure&) {
        }
        if (builds) {
          fail(section, "pins-before-masses",
               format_text(tr("%s failed (%s), and with no pins it builds: the pins are set before "
                              "the masses exist (set "
                              "masses[i]->pinned after the masses are made)"),
                           request_text(r).c_str(), e.what()));
          return false;
        }
      }
      fail(section, "constructor-failed", e.what());
      return false;
    }
    if (!check_built(r, rope, i < 2, section)) return false;
  }
  pass(section, "small-ropes",
       tr("the small ropes the probes below use (3 masses, 2 masses, a hanging spring) are built "
          "right too"));
  return true;
}

}  // namespace springlab::homework
