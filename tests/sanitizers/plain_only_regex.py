#!/usr/bin/env python3
"""Prints the CTest -E regex of the tests the sanitizer step leaves to the plain step.

Reads `ctest -N` output on stdin and the rules of tests/sanitizers/plain-only.txt (its header
says what `one:` and `skip:` mean). Fails, naming the line, when a rule matches no test, so a
renamed test cannot slip back into the sanitizer step or out of it unnoticed.
"""
import re
import sys


def main() -> int:
    rules_path = sys.argv[1]
    names = [m.group(1) for m in (re.match(r"\s*Test\s+#\d+: (\S+)", line) for line in sys.stdin) if m]
    excluded = []
    for number, line in enumerate(open(rules_path, encoding="utf-8"), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        kind, _, name = (part.strip() for part in line.partition(":"))
        if kind == "one":
            family = [n for n in names if n.startswith(name + "/")]
            if len(family) < 2:
                sys.exit(f"{rules_path}:{number}: 'one: {name}' names no family of two or more tests")
            excluded += family[1:]
        elif kind == "skip":
            if name not in names:
                sys.exit(f"{rules_path}:{number}: 'skip: {name}' names no test")
            excluded.append(name)
        else:
            sys.exit(f"{rules_path}:{number}: expected 'one: FAMILY' or 'skip: TEST', got '{line}'")
    escape = lambda n: re.sub(r"([][.*+?^$()|\\])", r"\\\1", n)
    print("^(" + "|".join(escape(n) for n in excluded) + ")$" if excluded else "^$")
    return 0


if __name__ == "__main__":
    sys.exit(main())
