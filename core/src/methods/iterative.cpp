// The parts XPBD, local-global and VBD share (iterative.hpp): the inertial prediction, the end
// of the step, the vertex colouring and the Chebyshev weights.
#include "iterative.hpp"

#include <algorithm>

#include "springlab/fields.hpp"

namespace springlab {
namespace iterative {

void predict(const Model& model, const State& in, double h, Points& y, std::vector<double>& mass) {
  const int n = in.particle_count();
  y.resize(n, 3);
  mass.resize(n);
  for (int i = 0; i < n; ++i) {
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
}

void finish(const Model& model, const State& in, State& out, double h) {
  const int n = in.particle_count();
  for (int i = 0; i < n; ++i) {
    if (model.pinned(i)) {
      out.x.row(i) = in.x.row(i) + h * in.v.row(i);
      out.v.row(i) = in.v.row(i);
    } else {
      out.v.row(i) = (out.x.row(i) - in.x.row(i)) / h;
    }
  }
  out.t = in.t + h;
}

}  // namespace iterative

int iterations_for(Method method, const StepSettings& settings) {
  if (settings.iterations > 0) return settings.iterations;
  return std::max(1, method_info(method).default_iterations);
}

void colour_vertices(const Model& model, VertexBlockDescent& out) {
  const int n = model.particle_count(), springs = model.spring_count();
  // Each vertex's springs, compressed rows.
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
  // Greedy colours in index order.
  std::vector<int> colour(n, -1);
  std::vector<int> seen;  // seen[c] == i: colour c is taken by a neighbour of i
  int colours = 0;
  for (int i = 0; i < n; ++i) {
    for (int k = out.first[i]; k < out.first[i + 1]; ++k) {
      const int c = colour[out.other[k]];
      if (c >= 0) seen[c] = i;
    }
    int c = 0;
    while (c < colours && seen[c] == i) ++c;
    if (c == colours) {
      ++colours;
      seen.push_back(-1);
    }
    colour[i] = c;
  }
  out.colour_first.assign(colours + 1, 0);
  for (int i = 0; i < n; ++i) ++out.colour_first[colour[i] + 1];
  for (int c = 0; c < colours; ++c) out.colour_first[c + 1] += out.colour_first[c];
  out.order.resize(out.colour_first[colours]);
  std::vector<int> at(out.colour_first.begin(), out.colour_first.end() - 1);
  for (int i = 0; i < n; ++i) out.order[at[colour[i]]++] = i;
  out.colour_work.assign(colours, 0.0);  // a vertex and its springs: what a pass over it visits
  for (int i = 0; i < n; ++i) out.colour_work[colour[i]] += 1.0 + (out.first[i + 1] - out.first[i]);
  out.spans = model.spans.data();
  out.particles = n;
  out.springs = springs;
}

void colour_springs(const Model& model, SpringColouring& out) {
  const int n = model.particle_count(), springs = model.spring_count();
  std::vector<int> first(n + 1, 0), incident;  // each particle's springs, compressed rows
  for (int s = 0; s < springs; ++s) {
    ++first[model.spring_a[s] + 1];
    ++first[model.spring_b[s] + 1];
  }
  for (int i = 0; i < n; ++i) first[i + 1] += first[i];
  incident.resize(first[n]);
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (int s = 0; s < springs; ++s) {
    incident[fill[model.spring_a[s]]++] = s;
    incident[fill[model.spring_b[s]]++] = s;
  }
  std::vector<int> colour(springs, -1);
  std::vector<int> seen;  // seen[c] == s: colour c is taken at an end of s
  int colours = 0;
  for (int s = 0; s < springs; ++s) {
    for (const int end : {model.spring_a[s], model.spring_b[s]})
      for (int k = first[end]; k < first[end + 1]; ++k)
        if (const int c = colour[incident[k]]; c >= 0) seen[c] = s;
    int c = 0;
    while (c < colours && seen[c] == s) ++c;
    if (c == colours) {
      ++colours;
      seen.push_back(-1);
    }
    colour[s] = c;
  }
  out.colour_first.assign(colours + 1, 0);
  for (int s = 0; s < springs; ++s) ++out.colour_first[colour[s] + 1];
  for (int c = 0; c < colours; ++c) out.colour_first[c + 1] += out.colour_first[c];
  out.order.resize(springs);
  std::vector<int> at(out.colour_first.begin(), out.colour_first.end() - 1);
  for (int s = 0; s < springs; ++s) out.order[at[colour[s]]++] = s;
  out.spans = model.spans.data();
  out.particles = n;
  out.springs = springs;
}

double chebyshev_omega(int k, double rho, double omega_before) {
  if (k <= 1) return 1.0;
  if (k == 2) return 2.0 / (2.0 - rho * rho);
  return 4.0 / (4.0 - rho * rho * omega_before);
}

}  // namespace springlab
