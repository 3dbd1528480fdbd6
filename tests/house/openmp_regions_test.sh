#!/usr/bin/env bash
# One way into threads, in the built code: no OpenMP parallel region in the core library, not even
# one a header compiles in (Eigen shares its large dense products among OpenMP threads of its own
# under -fopenmp unless EIGEN_DONT_PARALLELIZE: core/CMakeLists.txt). A region is a call of the
# runtime's fork: GOMP_parallel* (GCC's libgomp) or __kmpc_fork_call (clang's libomp).
# threads_seam_test.sh reads the sources; this reads the objects, where a header's region shows.
# Usage: tests/house/openmp_regions_test.sh LIBRARY_OR_OBJECT
#          (exit 1 naming each object that forks a region)
#        tests/house/openmp_regions_test.sh --self-test COMPILER
#          (compiles a dense product with -fopenmp, and expects the check to name it; then with
#          EIGEN_DONT_PARALLELIZE, and expects it to pass)
set -euo pipefail

if [[ "${1:-}" == "--self-test" ]]; then
  compiler="${2:?the C++ compiler}"
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  printf '#include <Eigen/Core>\nEigen::MatrixXd product(const Eigen::MatrixXd& a) { return a * a; }\n' \
    >"$tmp/planted.cpp"
  eigen=(-I/usr/include/eigen3)
  "$compiler" -std=c++20 -O1 -fopenmp "${eigen[@]}" -c "$tmp/planted.cpp" -o "$tmp/parallel.o"
  "$compiler" -std=c++20 -O1 -fopenmp -DEIGEN_DONT_PARALLELIZE "${eigen[@]}" -c "$tmp/planted.cpp" \
    -o "$tmp/serial.o"
  set +e
  out=$(bash "$0" "$tmp/parallel.o" 2>&1); rc=$?
  set -e
  echo "\$ openmp_regions_test.sh parallel.o  -> exit $rc"
  echo "$out"
  [[ $rc -eq 1 ]] && grep -q 'parallel.o' <<<"$out" ||
    { echo "self-test: Eigen's product under -fopenmp was not named" >&2; exit 1; }
  bash "$0" "$tmp/serial.o" ||
    { echo "self-test: the product with EIGEN_DONT_PARALLELIZE was named" >&2; exit 1; }
  echo "self-test: the check names a region a header compiles in, and passes without one"
  exit 0
fi

target="${1:?a library or object}"
[[ -r "$target" ]] || { echo "openmp_regions_test: no such file: $target" >&2; exit 2; }
found=$(nm -A "$target" 2>/dev/null | grep -E ' U (GOMP_parallel[A-Za-z_]*|__kmpc_fork_call)$' || true)
if [[ -n "$found" ]]; then
  echo "OpenMP parallel regions in $target (one way into threads: core/src/dynamics/threads.hpp):"
  echo "$found"
  exit 1
fi
echo "no OpenMP parallel region in $target"
