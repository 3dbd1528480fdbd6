#include "draw/row_styles.hpp"

#include <cmath>
#include <cstddef>
#include <iterator>

namespace springlab::draw {

namespace {

// Colours: Okabe and Ito's palette for colour-blind viewers, on a dark background and a
// projector. The five compared most (every shipped scene's lanes are among explicit Euler,
// symplectic Euler, RK4, Verlet and implicit Euler) take its five most distinct hues, for
// protanopes and deuteranopes too: vermilion #E66100, sky blue #56B4E9, bluish green #00A87A,
// yellow #F0E442 and reddish purple #D985C7; the rest take orange #E69F00, light grey, slate
// #80999A and a violet, and are seldom beside the ones they resemble; the iterative rows (what
// games use) salmon #FF8080, lime #A6D854 and aquamarine #00FFE6, apart from the lecture's.
// Measured (tests/app/palette_test.cpp): the five lecture rows stay 7.8 CIEDE2000 apart or more
// under simulated protanopia, deuteranopia and tritanopia; the lanes a lesson shows together
// 7.5; any two rows 4; each at least 4.5:1 as text on the panels.
// Marks: the five compared most take the five most unlike shapes (a triangle up for the energy
// that climbs, a circle, a square, a diamond, a triangle down); each row has its own.
struct MethodStyle {
  Method id;
  RowStyle style;
};
constexpr MethodStyle kMethodStyles[] = {
    {Method::Euler, {{0.90f, 0.38f, 0.00f}, Mark::TriangleUp}},
    {Method::SymplecticEuler, {{0.34f, 0.71f, 0.91f}, Mark::Circle}},
    {Method::Midpoint, {{0.90f, 0.62f, 0.00f}, Mark::Plus}},
    {Method::ModifiedEuler, {{0.78f, 0.78f, 0.78f}, Mark::Cross}},
    {Method::RK4, {{0.00f, 0.66f, 0.48f}, Mark::Square}},
    {Method::AdaptiveEuler, {{0.50f, 0.60f, 0.60f}, Mark::RingCircle}},
    {Method::RK45, {{0.62f, 0.50f, 0.98f}, Mark::RingSquare}},
    {Method::ImplicitEuler, {{0.85f, 0.52f, 0.78f}, Mark::TriangleDown}},
    {Method::Verlet, {{0.94f, 0.89f, 0.26f}, Mark::Diamond}},
    {Method::XPBD, {{1.00f, 0.50f, 0.50f}, Mark::RingTriangleUp}},
    {Method::LocalGlobal, {{0.65f, 0.85f, 0.33f}, Mark::RingDiamond}},
    {Method::VBD, {{0.00f, 1.00f, 0.90f}, Mark::RingTriangleDown}},
};

// In the enum's order, so that a row's style is found by its id; tests/app/palette_test.cpp
// checks there is one for every built-in row.
constexpr bool styles_in_enum_order() {
  for (std::size_t i = 0; i < std::size(kMethodStyles); ++i)
    if (static_cast<std::size_t>(kMethodStyles[i].id) != i) return false;
  return true;
}
static_assert(styles_in_enum_order(), "kMethodStyles' rows must be in the order of enum Method");

// Rows added at run time take these colours in turn, apart from the built-in rows' (peach
// second: lesson 12 sets the second tableau beside implicit Euler's purple), then hues turned by
// the golden angle; and the built-in rows' marks again.
constexpr std::array<float, 3> kAddedColours[] = {
    {0.00f, 0.85f, 0.95f},  // cyan
    {1.00f, 0.78f, 0.55f},  // peach
    {0.80f, 0.60f, 0.35f},  // tan
    {0.55f, 0.62f, 1.00f},  // periwinkle
    {0.60f, 1.00f, 0.80f},  // mint
    {1.00f, 0.60f, 0.80f},  // pink
};

// The style of the row at `index` in a table whose first `built_in` rows have their own: the
// k-th added row (k = index - built_in) the k-th added colour, then a golden-angle hue.
RowStyle added_style(std::size_t index, std::size_t built_in) {
  const std::size_t k = index - built_in;
  RowStyle s{{}, kMethodStyles[index % std::size(kMethodStyles)].style.mark};
  if (k < std::size(kAddedColours)) {
    s.colour = kAddedColours[k];
  } else {
    const float hue = std::fmod(0.61803398875f * static_cast<float>(index), 1.0f);
    const auto channel = [&](float offset) {
      return 0.55f + 0.35f * std::cos(6.28318530718f * (hue + offset));
    };
    s.colour = {channel(0.0f), channel(-1.0f / 3.0f), channel(1.0f / 3.0f)};
  }
  return s;
}

// The IK solvers take the lecture rows' first three hues and shapes (vermilion, sky blue, bluish
// green): an IK scene shows no method beside them.
constexpr RowStyle kIkStyles[] = {
    {{0.90f, 0.38f, 0.00f}, Mark::TriangleUp},  // ccd
    {{0.34f, 0.71f, 0.91f}, Mark::Circle},      // fabrik
    {{0.00f, 0.66f, 0.48f}, Mark::Square},      // dls
};

}  // namespace

RowStyle method_style(Method method) {
  const auto index = static_cast<std::size_t>(method);
  if (index < std::size(kMethodStyles)) return kMethodStyles[index].style;
  return added_style(index, std::size(kMethodStyles));
}

RowStyle ik_solver_style(IkSolver solver) {
  return kIkStyles[static_cast<std::size_t>(solver) % std::size(kIkStyles)];
}

RowStyle row_style(const app::LaneRow& row) {
  switch (row.table) {
    case app::LaneRow::Table::Method:
      return method_style(static_cast<Method>(row.id));
    case app::LaneRow::Table::IkSolver:
      return ik_solver_style(static_cast<IkSolver>(row.id));
    case app::LaneRow::Table::Own:
      break;
  }
  return added_style(std::size(kMethodStyles) + static_cast<std::size_t>(row.id),
                     std::size(kMethodStyles));
}

}  // namespace springlab::draw
