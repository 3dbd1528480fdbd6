// The parts XPBD, local-global and VBD share (iterative.hpp): the inertial prediction, the end
// of the step, the vertex and spring colourings and the Chebyshev weights.
#include "iterative.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "springlab/fields.hpp"

namespace springlab {
namespace iterative {

void predict(const Model& model, const State& in, double h, Points& y, std::vector<double>& mass) {
  const int n = in.particle_count();
  y.resize(n, 3);
  mass.resize(n);
  each_particle_piece(n, [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {
      const Vec3 x = in.x.row(i).transpose(), v = in.v.row(i).transpose();
      if (model.pinned(i)) {
        y.row(i) = (x + h * v).transpose();
        mass[i] = model.mass[i];
        continue;
      }
      Vec3 a = model.gravity;
      for (const Attractor& field : model.attractors) a += field_acceleration(field, x);
      const double m = model.mass[i];
      mass[i] = m + h * model.drag;
      const Vec3 v_tilde = (m * v + h * (m * a + model.drag * model.wind)) / mass[i];
      y.row(i) = (x + h * v_tilde).transpose();
    }
  });
}

void finish(const Model& model, const State& in, State& out, double h) {
  each_particle_piece(in.particle_count(), [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {
      if (model.pinned(i)) {
        out.x.row(i) = in.x.row(i) + h * in.v.row(i);
        out.v.row(i) = in.v.row(i);
      } else {
        out.v.row(i) = (out.x.row(i) - in.x.row(i)) / h;
      }
    }
  });
  out.t = in.t + h;
}

}  // namespace iterative

int iterations_for(Method method, const StepSettings& settings) {
  if (settings.iterations > 0) return settings.iterations;
  return std::max(1, method_info(method).default_iterations);
}

namespace {

// Each particle's springs, compressed rows: first[i] to first[i + 1] of `spring`, in the springs'
// order, with the particle at each one's other end in `other`.
struct Incidence {
  std::vector<int> first, spring, other;
};

Incidence incidence(const Model& model) {
  const int n = model.particle_count(), springs = model.spring_count();
  Incidence out;
  out.first.assign(n + 1, 0);
  for (int s = 0; s < springs; ++s) {
    ++out.first[model.spring_a[s] + 1];
    ++out.first[model.spring_b[s] + 1];
  }
  for (int i = 0; i < n; ++i) out.first[i + 1] += out.first[i];
  out.spring.resize(out.first[n]);
  out.other.resize(out.first[n]);
  std::vector<int> fill(out.first.begin(), out.first.end() - 1);
  for (int s = 0; s < springs; ++s) {
    const int a = model.spring_a[s], b = model.spring_b[s];
    out.spring[fill[a]] = s, out.other[fill[a]++] = b;
    out.spring[fill[b]] = s, out.other[fill[b]++] = a;
  }
  return out;
}

// Greedy colours in index order: item i takes the least colour that none of the items
// neighbours(i, mark) marks (mark(j) for each neighbour j) has. Each item's colour; `colours` the
// count.
template <typename Neighbours>
std::vector<int> greedy_colours(int items, const Neighbours& neighbours, int& colours) {
  std::vector<int> colour(items, -1);
  std::vector<int> seen;  // seen[c] == i: colour c is taken by a neighbour of i
  colours = 0;
  for (int i = 0; i < items; ++i) {
    neighbours(i, [&](int j) {
      if (const int c = colour[j]; c >= 0) seen[c] = i;
    });
    int c = 0;
    while (c < colours && seen[c] == i) ++c;
    if (c == colours) {
      ++colours;
      seen.push_back(-1);
    }
    colour[i] = c;
  }
  return colour;
}

// The items grouped by colour, ascending in each: colour c is order[first[c], first[c + 1]).
void group_by_colour(const std::vector<int>& colour, int colours, std::vector<int>& first,
                     std::vector<int>& order) {
  first.assign(colours + 1, 0);
  for (const int c : colour) ++first[c + 1];
  for (int c = 0; c < colours; ++c) first[c + 1] += first[c];
  order.resize(colour.size());
  std::vector<int> at(first.begin(), first.end() - 1);
  for (int i = 0; i < static_cast<int>(colour.size()); ++i) order[at[colour[i]]++] = i;
}

}  // namespace

void colour_vertices(const Model& model, VertexBlockDescent& out) {
  const int n = model.particle_count();
  Incidence springs_at = incidence(model);
  out.first = std::move(springs_at.first);
  out.spring = std::move(springs_at.spring);
  out.other = std::move(springs_at.other);
  int colours = 0;
  const std::vector<int> colour = greedy_colours(
      n,
      [&](int i, const auto& mark) {
        for (int k = out.first[i]; k < out.first[i + 1]; ++k) mark(out.other[k]);
      },
      colours);
  group_by_colour(colour, colours, out.colour_first, out.order);
  out.colour_work.assign(colours, 0.0);  // a vertex and its springs: what a pass over it visits
  for (int i = 0; i < n; ++i) out.colour_work[colour[i]] += 1.0 + (out.first[i + 1] - out.first[i]);
  out.spans = model.spans.data();
  out.particles = n;
  out.springs = model.spring_count();
}

void colour_springs(const Model& model, SpringColouring& out) {
  const int springs = model.spring_count();
  const Incidence at = incidence(model);
  int colours = 0;
  const std::vector<int> colour = greedy_colours(
      springs,
      [&](int s, const auto& mark) {
        for (const int end : {model.spring_a[s], model.spring_b[s]})
          for (int k = at.first[end]; k < at.first[end + 1]; ++k) mark(at.spring[k]);
      },
      colours);
  group_by_colour(colour, colours, out.colour_first, out.order);
  out.springs_in_order.resize(out.order.size());
  for (std::size_t k = 0; k < out.order.size(); ++k) {
    const int sp = out.order[k];
    out.springs_in_order[k] = {model.spring_a[sp], model.spring_b[sp], model.spring_material[sp],
                               model.rest_length[sp]};
  }
  out.spans = model.spans.data();
  out.particles = model.particle_count();
  out.springs = springs;
}

double chebyshev_omega(int k, double rho, double omega_before) {
  if (k <= 1) return 1.0;
  if (k == 2) return 2.0 / (2.0 - rho * rho);
  return 4.0 / (4.0 - rho * rho * omega_before);
}

}  // namespace springlab
