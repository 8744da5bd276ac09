#!/usr/bin/env python3
"""Compares the loads.csv of runs of one case on different process counts.

  compare_loads.py REFERENCE/loads.csv OTHER/loads.csv [...]

For each OTHER: the rows it shares with REFERENCE (same increment and
surface), the largest difference of a force component relative to the
largest press load of REFERENCE (stroke and time: relative to their value),
where it is, and whether both have the same rows. Prints one line per OTHER;
exits 1 when the rows differ.

When REFERENCE remeshed (summary.json beside its loads.csv), the rows are
compared up to its first remesh; after it the runs have other meshes (a
remesh is not a continuous function of the nodes' round-off) and often rows
at other times, so the forces of OTHER are interpolated linearly in time at
REFERENCE's rows: the largest and the mean difference."""
import bisect
import csv
import json
import os
import sys


def rows(path):
    with open(path) as f:
        return {(r["increment"], r["surface"]): r for r in csv.DictReader(f)}


def peak_load(table):
    """The largest force component of a run: the scale of its differences."""
    return max(max(abs(float(r[k])) for k in ("model_Fx_N", "model_Fy_N", "model_Fz_N")) for r in table.values()) or 1.0


def compare(reference, other):
    """(largest relative difference, same rows) of `other` against `reference`."""
    worst, _, same = largest_difference(reference, other)
    return worst, same


def largest_difference(reference, other, columns=("model_Fx_N", "model_Fy_N", "model_Fz_N", "stroke_mm", "time_s")):
    """(largest relative difference, (column, increment, surface) of it, same rows)."""
    peak = peak_load(reference)
    shared = reference.keys() & other.keys()
    worst, where = 0.0, None
    for key in sorted(shared):
        for k in columns:
            scale = peak if k.endswith("_N") else max(abs(float(reference[key][k])), 1e-300)
            difference = abs(float(reference[key][k]) - float(other[key][k])) / scale
            if difference > worst:
                worst, where = difference, (k, *key)
    return worst, where, shared == reference.keys() == other.keys()


def first_remesh(loads):
    """Increment of the first remesh of the run that wrote `loads`, or None.
    The remesh follows that increment: row k of loads.csv is the geometry
    after k increments, so from that increment's row on the loads are
    solved on the new mesh."""
    try:
        with open(os.path.join(os.path.dirname(loads), "summary.json")) as f:
            remeshes = json.load(f).get("remeshing", {}).get("remeshes", [])
    except (OSError, ValueError):
        return None
    return min((r["increment"] for r in remeshes), default=None)


def up_to(table, increment):
    return {key: r for key, r in table.items() if int(key[0]) <= increment}


def at_equal_time(reference, other, after, columns=("model_Fx_N", "model_Fy_N", "model_Fz_N")):
    """{column: differences} of the forces past increment `after`, `other`
    interpolated linearly in time at `reference`'s rows, relative to the
    peak load."""
    peak = peak_load(reference)
    series = {}
    for r in sorted(other.values(), key=lambda r: float(r["time_s"])):
        series.setdefault(r["surface"], []).append(r)
    times = {surface: [float(r["time_s"]) for r in rows_of] for surface, rows_of in series.items()}
    differences = {k: [] for k in columns}
    for (increment, surface), r in reference.items():
        t, ts = float(r["time_s"]), times.get(surface, [])
        if int(increment) <= after or not ts or not ts[0] <= t <= ts[-1]:
            continue
        i = bisect.bisect_left(ts, t)
        a, b = series[surface][max(i - 1, 0)], series[surface][i]
        w = (t - ts[i - 1]) / (ts[i] - ts[i - 1]) if i > 0 and ts[i] > ts[i - 1] else 1.0
        for k in columns:
            value = (1 - w) * float(a[k]) + w * float(b[k])
            differences[k].append(abs(value - float(r[k])) / peak)
    return differences


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    everything = rows(sys.argv[1])
    remesh = first_remesh(sys.argv[1])
    reference = everything if remesh is None else up_to(everything, remesh - 1)
    status = 0
    for path in sys.argv[2:]:
        other_everything = rows(path)
        other = other_everything if remesh is None else up_to(other_everything, remesh - 1)
        worst, where, same = largest_difference(reference, other)
        at = f" ({where[0]}, increment {where[1]}, {where[2]})" if where else ""
        press = largest_difference(reference, other, ("model_Fz_N",))[0]
        line = f"{path}: {len(reference)} rows"
        if remesh is not None:
            line += f" up to the first remesh (increment {remesh})"
        line += f", largest difference {worst:.2e} of the peak load{at}; press load Fz {press:.2e}"
        line += "" if same else " (the rows differ)"
        if remesh is not None:
            differences = at_equal_time(everything, other_everything, remesh - 1)
            press = differences["model_Fz_N"]
            largest = max((d for column in differences.values() for d in column), default=0.0)
            line += (f"; after it, at equal time ({len(everything) - len(reference)} / "
                     f"{len(other_everything) - len(other)} rows): largest {largest:.2e}, press load Fz"
                     f" {max(press, default=0.0):.2e} (mean {sum(press) / max(len(press), 1):.2e})")
        print(line)
        status |= not same
    return status


if __name__ == "__main__":
    sys.exit(main())
