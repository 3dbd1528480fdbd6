"""What the house checks share (tests/house/*_test.py): the floor option that keeps a scan which
reads nothing from passing, and a self-test's verdict on its planted defects."""
import sys


def take_floor(args, flag, default):
    """Removes `flag N` from args, returning N (or `default` when it is not given)."""
    if flag not in args:
        return default
    k = args.index(flag)
    value = int(args[k + 1])
    del args[k:k + 2]
    return value


def self_test_verdict(problems, passed):
    """Prints each problem and the verdict, `passed` saying what the check did when there are none,
    and exits 1 on any problem."""
    for problem in problems:
        print(f"self-test: {problem}", file=sys.stderr)
    print("self-test: " + ("FAILED" if problems else passed))
    sys.exit(1 if problems else 0)
