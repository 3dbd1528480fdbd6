#include "homework/rope_lane.hpp"

#include <cmath>
#include <deque>
#include <iterator>
#include <optional>

#include "springlab/text.hpp"

namespace springlab::app {

using namespace homework;

namespace {

// Steps are asked for a batch at a time, ahead of the lane: a round trip to the runner costs more
// than a rope's step (and a call into the page's JavaScript some), and while nothing from outside
// changes the lane's state (a reset, a drag, a slider, a new h) the steps it will ask for next are
// those the runner would make anyway. A batch that fails is taken again a step at a time, so that a
// crash is told at its own step.
constexpr int kAhead = 32;

struct StudentLane {
  std::shared_ptr<RopeCode> code;
  Step step;
  bool springlab_rope =
      false;  // built through build_exercise (the code's constructor is not right)
  std::optional<RopeRequest> built;  // the rope the runner holds
  State made;  // the state the lane was last given (the runner's, when synced)
  bool synced = false;
  std::deque<RopeState> ahead;  // the runner's next states, from `made`
  double ahead_h = 0.0;
  Vec2 ahead_g = Vec2::Zero();
  bool one_at_a_time = false;  // after a failed batch
};

bool same(const RopeRequest& a, const RopeRequest& b) {
  return a.nodes == b.nodes && a.node_mass == b.node_mass && a.k == b.k && a.pinned == b.pinned;
}

// The model as the exercise's constructor takes it: a rope of n masses, each spring joining
// neighbours, one k, one rest length, one node mass. Anything else cannot be built by it.
RopeRequest as_rope(const Model& model, const State& in) {
  const int n = model.particle_count();
  auto refuse = [](const char* why) {
    throw StepFailure(std::string(tr("your rope code steps a rope: ")) + tr(why) +
                      tr(" (open the rope scene)"));
  };
  if (n < 2 || model.spring_count() != n - 1) refuse(N_("this scene is not one rope"));
  std::vector<int> joined(n, 0);
  for (int s = 0; s < model.spring_count(); ++s) {
    if (model.spring_b[s] != model.spring_a[s] + 1)
      refuse(N_("a spring joins masses that are not neighbours"));
    if (model.ks(s) != model.ks(0) || model.rest_length[s] != model.rest_length[0])
      refuse(N_("its springs differ"));
    ++joined[model.spring_a[s]];
  }
  for (int i = 0; i + 1 < n; ++i)
    if (joined[i] != 1) refuse(N_("this scene is not one rope"));
  for (int i = 1; i < n; ++i)
    if (model.mass[i] != model.mass[0]) refuse(N_("its masses differ"));
  RopeRequest r;
  r.nodes = n;
  r.node_mass = model.mass[0];
  r.k = model.ks(0);
  for (int i = 0; i < n; ++i)
    if (model.pinned(i)) r.pinned.push_back(i);
  // Start and end along the rope as it lies, at its rest length: the constructor takes its
  // springs' rest lengths from them (the state is then set as the lane's).
  r.start = in.x.row(0).head<2>().transpose();
  Vec2 along = in.x.row(n - 1).head<2>().transpose() - r.start;
  along = along.norm() > 0.0 ? Vec2(along.normalized()) : Vec2(1.0, 0.0);
  r.end = r.start + along * (model.rest_length[0] * (n - 1));
  return r;
}

RopeState next_state(StudentLane& lane, const Model& model, const State& in, double h,
                     const Vec2& gravity) {
  const int n = in.particle_count();
  const bool continues = lane.synced && lane.made.x.rows() == in.x.rows() && lane.made.x == in.x &&
                         lane.made.v == in.v;
  if (continues && !lane.ahead.empty() && lane.ahead_h == h && lane.ahead_g == gravity) {
    RopeState next = std::move(lane.ahead.front());
    lane.ahead.pop_front();
    return next;
  }
  lane.ahead.clear();
  if (!continues) {
    RopeState s(n);
    for (int i = 0; i < n; ++i) {
      s[i].x = in.x.row(i).head<2>().transpose();
      s[i].v = in.v.row(i).head<2>().transpose();
      s[i].x_last = model.pinned(i) ? s[i].x : Vec2(s[i].x - h * s[i].v);
    }
    lane.code->set_state(s);
  }
  std::vector<RopeState> run =
      lane.code->simulate(lane.step, h, gravity, lane.one_at_a_time ? 1 : kAhead);
  lane.ahead.assign(std::make_move_iterator(run.begin() + 1), std::make_move_iterator(run.end()));
  lane.ahead_h = h;
  lane.ahead_g = gravity;
  return std::move(run.front());
}

void step_lane(StudentLane& lane, const Model& model, const State& in, State& out, double h) {
  const int n = in.particle_count();
  const RopeRequest request = as_rope(model, in);
  const Vec2 gravity = model.gravity.head<2>();
  RopeState next;
  for (bool retried = false;; retried = true) {
    try {
      if (!lane.built || !same(*lane.built, request)) {
        if (lane.springlab_rope)
          lane.code->build_exercise(request);
        else
          lane.code->build(request);
        lane.built = request;
        lane.synced = false;
        lane.ahead.clear();
      }
      next = next_state(lane, model, in, h, gravity);
      break;
    } catch (const CodeFailure& e) {
      lane.built.reset();  // the runner starts afresh
      lane.synced = false;
      lane.ahead.clear();
      if (retried || lane.one_at_a_time) throw StepFailure(e.what());
      lane.one_at_a_time = true;  // once more, a step at a time: the failure at its own step
    }
  }
  if (static_cast<int>(next.size()) != n)
    throw StepFailure(tr("the rope code changed its number of masses"));
  out.x = in.x;
  out.v = in.v;
  bool held_moved = false;
  for (int i = 0; i < n; ++i) {
    out.x.row(i).head<2>() = next[i].x.transpose();
    out.v.row(i).head<2>() =
        (lane.step == Step::Verlet ? Vec2((next[i].x - in.x.row(i).head<2>().transpose()) / h)
                                   : next[i].v)
            .transpose();
    // A held particle moves with its prescribed velocity, as every row moves it: then the runner's
    // rope is no longer the lane's.
    if (model.pinned(i) && in.v.row(i).squaredNorm() > 0.0) {
      out.x.row(i) = in.x.row(i) + h * in.v.row(i);
      out.v.row(i) = in.v.row(i);
      held_moved = true;
    }
  }
  out.t = in.t + h;
  lane.made = out;
  lane.synced = !held_moved;  // else the runner's state is set from the lane's next time
  if (held_moved) lane.ahead.clear();
}

}  // namespace

bool is_one_rope(const Model& model) {
  try {
    State s;
    s.resize(model.particle_count());
    s.x.setZero();
    s.v.setZero();
    as_rope(model, s);
    return true;
  } catch (const StepFailure&) {
    return false;
  }
}

OwnStep rope_lane_step(std::shared_ptr<RopeCode> code, Step step, bool springlab_rope) {
  auto lane = std::make_shared<StudentLane>();
  lane->code = std::move(code);
  lane->step = step;
  lane->springlab_rope = springlab_rope;
  return [lane](const Model& model, const State& in, State& out, double h, Workspace&) {
    step_lane(*lane, model, in, out, h);
  };
}

}  // namespace springlab::app
