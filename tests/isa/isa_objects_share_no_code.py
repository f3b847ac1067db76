#!/usr/bin/env python3
"""Fails if an object of the archive compiled for an instruction-set extension (its name says
which: _avx2, _avx512, _fma) defines a weak function that another object defines too.

Inline functions and template instances are emitted as weak symbols in every object that does not
inline them, and the linker keeps one copy for all callers. A copy compiled with -mavx2 kept for
the scalar kernels makes MyGL die of SIGILL on a CPU without AVX (it did: NarrowRows' constructor).

usage: isa_objects_share_no_code.py NM ARCHIVE
"""
import re
import subprocess
import sys

ISA_OBJECT = re.compile(r"_(avx2|avx512|fma)[^/]*\.o$")
MEMBER = re.compile(r"^Symbols from .*\[(.*)\]:$")


def weak_functions_by_object(nm, archive):
    """Every member of the archive, with the weak functions it defines."""
    # Code only: weak data (constants, the personality routine's reference) runs no instruction.
    listing = subprocess.run([nm, "--defined-only", "--format=sysv", archive], check=True, capture_output=True,
                             text=True).stdout
    symbols, member = {}, None
    for line in listing.splitlines():
        header = MEMBER.match(line)
        if header:
            member = header.group(1)
            symbols.setdefault(member, set())
            continue
        fields = [field.strip() for field in line.split("|")]  # name|value|class|type|size|line|section
        if member and len(fields) >= 4 and fields[2] == "W" and fields[3] == "FUNC":
            symbols[member].add(fields[0])
    return symbols


def main():
    nm, archive = sys.argv[1:3]
    symbols = weak_functions_by_object(nm, archive)
    isa = {member: names for member, names in symbols.items() if ISA_OBJECT.search(member)}
    if not isa:
        sys.exit(f"no object named for an instruction set in {archive}: the check checks nothing")
    failures = []
    for member, names in sorted(isa.items()):
        for other, other_names in sorted(symbols.items()):
            if other != member:
                failures += [(member, other, name) for name in sorted(names & other_names)]
    for member, other, name in failures:
        demangled = subprocess.run(["c++filt", name], capture_output=True, text=True).stdout.strip() or name
        print(f"{member} and {other} both define {demangled}")
    if failures:
        sys.exit(f"{len(failures)} weak functions shared: force-inline them or give them internal linkage")
    print(f"{len(isa)} instruction-set objects checked against {len(symbols) - len(isa)} others: nothing shared")


if __name__ == "__main__":
    main()
