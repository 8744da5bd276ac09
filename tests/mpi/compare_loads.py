#!/usr/bin/env python3
"""Compares the loads.csv of runs of one case on different process counts.

  compare_loads.py REFERENCE/loads.csv OTHER/loads.csv [...]

For each OTHER: the rows it shares with REFERENCE (same increment and
surface), the largest difference of a force component relative to the
largest press load of REFERENCE, and whether both have the same rows. Prints
one line per OTHER; exits 1 when the rows differ."""
import csv
import sys


def rows(path):
    with open(path) as f:
        return {(r["increment"], r["surface"]): r for r in csv.DictReader(f)}


def compare(reference, other):
    """(largest relative difference, same rows) of `other` against `reference`."""
    peak = max(max(abs(float(r[k])) for k in ("Fx_N", "Fy_N", "Fz_N")) for r in reference.values()) or 1.0
    shared = reference.keys() & other.keys()
    worst = 0.0
    for key in shared:
        for k in ("Fx_N", "Fy_N", "Fz_N", "stroke_mm", "time_s"):
            scale = peak if k.endswith("_N") else max(abs(float(reference[key][k])), 1e-300)
            worst = max(worst, abs(float(reference[key][k]) - float(other[key][k])) / scale)
    return worst, shared == reference.keys() == other.keys()


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    reference = rows(sys.argv[1])
    status = 0
    for path in sys.argv[2:]:
        worst, same = compare(reference, rows(path))
        print(f"{path}: {len(reference)} rows, largest difference {worst:.2e} of the peak load"
              + ("" if same else " (the rows differ)"))
        status |= not same
    return status


if __name__ == "__main__":
    sys.exit(main())
