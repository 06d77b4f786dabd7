"""Checks that the instruction-set copies of the pair loops in a built sphv are vector code.

The pair loops' speed rests on GCC vectorising them (sph/hydro/pairs.hpp): a branch or a nested
loop that it does not unroll leaves a copy scalar without any result changing, and only a
profile would show it. This reads the binary's disassembly (objdump) and requires every AVX2 copy
of a pair loop (particles_in_avx2, listed_in_avx2, batch_geometry_avx2) to hold packed-double
arithmetic on 256-bit registers and every AVX-512 copy on 512-bit registers, except the loops
listed in SCALAR below, each with why it is scalar. A loop that calls pow (the
general lambda forms of (25), rho^lambda per pair) cannot be vectorised by GCC without the vector
math library and is not held to it.

Usage: pair_loops_vectorised.py SPHV_BINARY. Exit 0 pass, 1 a loop is scalar, 77 skipped (no
AVX2 copies in this build: not x86-64 GCC), 3 objdump failed.
"""
import re
import subprocess
import sys

# Loops known to be scalar: name fragment -> why.
SCALAR = {
    "sph::sum_over_pairs<": "the kernel interpolants and operators (pairs_of): a branch per pair on |r_ij| < h_ij after "
                            "the vectorised pair geometry",
    "sph::TwoPassConduction<": "not vectorised: the two-pass conduction's pair term reads grad T as Vec<D> records "
                               "(the heat and laplacian cases' flux forms)",
}
COPY = re.compile(r"^void sph::(?:particles_in|listed_in|detail::batch_geometry)_(avx2|avx512)<")
REGISTER = {"avx2": "%ymm", "avx512": "%zmm"}  # the vector registers each copy's arithmetic must use
PACKED_DOUBLE = re.compile(r"^v\w+pd$")


def functions(binary):
    """(name, instructions) of every function in the binary's text."""
    out = subprocess.run(["objdump", "-d", "-C", "--no-show-raw-insn", binary], capture_output=True, text=True)
    if out.returncode != 0:
        print(f"pair_loops_vectorised: objdump failed: {out.stderr.strip()}")
        sys.exit(3)
    name, body = None, []
    for line in out.stdout.splitlines():
        m = re.match(r"^[0-9a-f]+ <(.*)>:$", line)
        if m:
            if name:
                yield name, body
            name, body = m.group(1), []
        elif name and "\t" in line:
            body.append(line.split("\t")[-1].strip())
    if name:
        yield name, body


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    seen = {k: 0 for k in REGISTER}
    scalar, exempt = [], 0
    for name, body in functions(sys.argv[1]):
        m = COPY.match(name)
        if not m:
            continue
        copy = m.group(1)
        seen[copy] += 1
        if any(k in name for k in SCALAR) or any(i.startswith("call") and "<pow@plt>" in i for i in body):
            exempt += 1
            continue
        if not any(REGISTER[copy] in i and PACKED_DOUBLE.match(i.split()[0]) for i in body if i):
            scalar.append(f"{copy}: {name[:400]}")
    if seen["avx2"] == 0:
        print("pair_loops_vectorised: skipped: no AVX2 copies of the pair loops in this build (not x86-64 GCC)")
        sys.exit(77)
    print(f"pair_loops_vectorised: {seen['avx2']} AVX2 and {seen['avx512']} AVX-512 copies of pair loops, "
          f"{exempt} known to be scalar (listed with their reasons), {len(scalar)} scalar where they should be vector code")
    for s in scalar:
        print("  scalar:", s)
    sys.exit(1 if scalar else 0)


if __name__ == "__main__":
    main()
