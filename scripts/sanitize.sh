#!/usr/bin/env bash
# The checking build: the core tests and the loaders' fuzz targets built with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer (and LeakSanitizer), into build-sanitize/,
# then run: the core tests must be clean, and each fuzz target runs for a bounded time
# (tests/fuzz/README.md). scripts/test.sh runs it after the normal suite.
# Usage: scripts/sanitize.sh [ctest options, e.g. -L fuzz or -R Scene]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${SPRINGLAB_SANITIZE_BUILD_DIR:-${SPRINGLAB_BUILD_DIR:-$root/build}-sanitize}"
# No app or benchmarks: the core is what the sanitizers check (the app's GL drivers are not
# built with them, and report what is theirs).
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DSPRINGLAB_SANITIZE=ON -DSPRINGLAB_FUZZ=ON -DSPRINGLAB_BUILD_APP=OFF -DSPRINGLAB_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --parallel "$(nproc)"
cd "$build"
export UBSAN_OPTIONS="print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
# Two tests at once, each with its OpenMP threads: waiting threads sleep instead of spinning.
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"

# Left out here, and only here: Determinism.ThreadCountDoesNotChangeABit runs a 48 x 48 cloth
# with five methods at 1, 2 and 3 threads, and two of them diverge, each divergence estimating
# w_max by power iteration for its message; a few seconds in the Release build, over 15 minutes
# with the sanitizers (Eigen's small matrices at -O1, every access checked). The code it runs,
# the parallel force pass included, is run by the other core tests (cloth-sphere's 32 x 32
# cloth is above the parallel threshold and has four particle blocks). The same for the limits
# test (Scenes/Limits.*: every shipped scene run at 0.95 and 1.25 of each method's limit, tens
# of seconds in Release, past the 600 s timeout under the sanitizers); the analysis it checks
# is run here by the stability tests. And the two longest bisections of the stable step by runs
# (Analysis.RunsFindTheAnalysisLimits, Sweep.OnTheSpringOrdersAndStabilityLimits...: a minute
# each here, a few seconds in Release): measured_limit and the sweep run here in the other Sweep
# and Analysis tests. And the energy audit's runs both ways (AuditSilence.*, AuditCatches.*: 546
# single springs, the rope for 68 s and the cloth for 10 s, and clothes past their limits, 25 s
# in Release): the audit's rule, its transient growth and its lower bound are run here by
# EnergyAuditRule.*, TransientGrowth.* and LowestEnergy.*, and a caught run by the Stability tests.
# And the iterative rows' two long sweeps (Iterative.BoundedAtOneStepAFrameOnEveryScene: eight
# scenes, three methods, two steps, 10 s each; Iterative.RunsFindThemStableAtAnyStep: bisections
# up to h w = 1000; 40 s and 46 s here, a few in Release): XPBD's, local-global's and VBD's steps
# run here in the other Iterative tests (converged to the backward-Euler step, Chebyshev, softness,
# factorisation, colouring) and in the momentum tests. And three long numerical runs (measured
# here on 2026-11-28: 34 s, 23 s and 19 s; a few seconds in Release) whose code runs here in
# shorter tests: the balance to its tolerance on every scene (Equilibrium.BalancesTheForces...;
# the balance runs in Equilibrium.WithNoWeight... and every analysis), implicit midpoint's energy
# over a long swing (TableauMethods.ImplicitMidpointsEnergy...; the DIRK stages run in the other
# TableauMethods tests) and a sweep taken in steps (Sweep.InSteps...; the sweep with its workers
# runs in Sweep.TheNumberOfWorkersChangesNoResult). And every implicit tableau on every scene
# (TableauMethods.EveryImplicitTableauRuns...: 40 s here on 2026-11-29, the longest test left, a
# 1.5 s in Release): the stages' Newton solves run here on a free cloth for every row
# (Momentum.EachRowKeepsWhatItSays) and on a pinned rope (TableauMethods.DiagonallyImplicit...).
ctest --output-on-failure --parallel "$(nproc)" --timeout 600 -L 'core|fuzz' \
  -E '^Determinism\.ThreadCountDoesNotChangeABit$|^Scenes/Limits\.|^Analysis\.RunsFindTheAnalysisLimits$|^Sweep\.OnTheSpringOrdersAndStabilityLimitsAreThoseOfNumericsMd$|^Audit(Silence|Catches)\.|^Iterative\.(BoundedAtOneStepAFrameOnEveryScene|RunsFindThemStableAtAnyStep)$|^Equilibrium\.BalancesTheForcesToItsStatedTolerance$|^TableauMethods\.ImplicitMidpointsEnergyErrorStaysBoundedOnASwingingRope$|^Sweep\.InStepsItIsTheSameSweep$|^TableauMethods\.EveryImplicitTableauRunsEverySceneWhereImplicitEulerDoes$' "$@"
