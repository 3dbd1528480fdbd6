"""Homework 8 in Python: a step of your own, checked.

Write one step of a method as a function over the whole state,

    def my_step(x, v, force, h):
        a = force(x, v)          # the core's accelerations f / m, shape (N, 3); 0 for a pinned particle
        v = v + h * a
        return x + h * v, v      # semi-implicit Euler

and springlab says what it is:

    import springlab.homework
    report = springlab.homework.check(my_step)
    print(report)                # which of springlab's rows it is, its order, stability and energy
    report.method                # "symplectic-euler", or None for none of them

The same function steps a scene beside springlab's own rows:

    sim = springlab.Simulation("rope", method=my_step, steps=600)
    sim.run()

`springlab homework check rope.cpp` checks the exercise's C++ (its constructor, simulateEuler and
simulateVerlet) with the same checker.
"""

from ._springlab import HomeworkReport, _homework_check

__all__ = ["check", "HomeworkReport"]


def check(fn, name=None):
    """Check fn(x, v, force, h) -> (x, v): which of springlab's explicit fixed-step rows it is (on a
    rope falling from rest, each step from fn's own state, to rounding), whether it holds a pin,
    and its order, stability and energy on a spring against that row's. Returns a HomeworkReport;
    an exception in fn is reported in it, with the call it happened on."""
    return _homework_check(fn, name if name is not None else getattr(fn, "__name__", "fn"))
