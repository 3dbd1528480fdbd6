// What the charts plot: per lane, a few quantities every kind has (its simulation's), sampled once
// a frame, the last kCapacity samples kept (20 s at 60 frames a second). What only one kind has
// its kind samples into the lane's part (scene_kind.hpp: an IK lane's distance to the target, a
// mass-spring lane's momentum), as long as these.
#pragma once

#include <cstddef>
#include <vector>

namespace springlab::app {

// A fixed-capacity series; index 0 is the oldest kept sample.
class Series {
 public:
  Series() : values_(1200) {}
  explicit Series(std::size_t capacity) : values_(capacity) {}
  void push(double x) {
    values_[(start_ + size_) % values_.size()] = x;
    if (size_ < values_.size())
      ++size_;
    else
      start_ = (start_ + 1) % values_.size();
  }
  void clear() { start_ = size_ = 0; }
  std::size_t size() const { return size_; }
  double operator[](std::size_t i) const { return values_[(start_ + i) % values_.size()]; }
  double back() const { return (*this)[size_ - 1]; }

 private:
  std::vector<double> values_;
  std::size_t start_ = 0, size_ = 0;
};

struct History {
  Series t, kinetic, potential, total, dissipated;
  Series net;   // E - E0 - W (Simulation::net_energy): with `dissipated`, the method's own losses
  Series x, v;  // the watched particle: its coordinate along the watched axis, and velocity
  Series exact_x;   // the exact solution there, where the scene has one (else empty)
  Series step;      // adaptive methods: the internal step their controller chose (s)
  Series rejected;  // adaptive methods: tries thrown away so far
  void clear() {
    for (Series* s :
         {&t, &kinetic, &potential, &total, &dissipated, &net, &x, &v, &exact_x, &step, &rejected})
      s->clear();
  }
};

}  // namespace springlab::app
