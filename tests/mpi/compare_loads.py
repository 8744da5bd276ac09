#!/usr/bin/env python3
"""Compares the loads.csv of runs of one case on different process counts.

  compare_loads.py REFERENCE/loads.csv OTHER/loads.csv [...]

For each OTHER: the rows it shares with REFERENCE (same increment and
surface), the largest difference of a force component relative to the
largest press load of REFERENCE (stroke and time: relative to their value),
where it is, and whether both have the same rows. Prints one line per OTHER;
exits 1 when the rows differ."""
import csv
import sys


def rows(path):
    with open(path) as f:
        return {(r["increment"], r["surface"]): r for r in csv.DictReader(f)}


def compare(reference, other):
    """(largest relative difference, same rows) of `other` against `reference`."""
    worst, _, same = largest_difference(reference, other)
    return worst, same


def largest_difference(reference, other, columns=("Fx_N", "Fy_N", "Fz_N", "stroke_mm", "time_s")):
    """(largest relative difference, (column, increment, surface) of it, same rows)."""
    peak = max(max(abs(float(r[k])) for k in ("Fx_N", "Fy_N", "Fz_N")) for r in reference.values()) or 1.0
    shared = reference.keys() & other.keys()
    worst, where = 0.0, None
    for key in sorted(shared):
        for k in columns:
            scale = peak if k.endswith("_N") else max(abs(float(reference[key][k])), 1e-300)
            difference = abs(float(reference[key][k]) - float(other[key][k])) / scale
            if difference > worst:
                worst, where = difference, (k, *key)
    return worst, where, shared == reference.keys() == other.keys()


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    reference = rows(sys.argv[1])
    status = 0
    for path in sys.argv[2:]:
        other = rows(path)
        worst, where, same = largest_difference(reference, other)
        at = f" ({where[0]}, increment {where[1]}, {where[2]})" if where else ""
        press = largest_difference(reference, other, ("Fz_N",))[0]
        print(f"{path}: {len(reference)} rows, largest difference {worst:.2e} of the peak load{at};"
              f" press load Fz {press:.2e}" + ("" if same else " (the rows differ)"))
        status |= not same
    return status


if __name__ == "__main__":
    sys.exit(main())
