#!/usr/bin/env python3
"""A real CARMEN log as another robot or sensor would have recorded it.

Usage: scripts/perturb_carmen_log.py IN.log[.gz] OUT.log VARIANT[@WHERE]

The scans, their timing and the reference poses stay the log's own; only
what the variant names changes, so the estimate can still be scored against
the corrected poses (issue 12: failure classes reproduced on real data, at
the real logs' spacing of a scan per 1-3 s and up to 80 deg, which the
simulated samples at 5 Hz do not have).

Variants (WHERE: the fraction of the scans where a ten-scan fault starts,
default 1/3; for noisy, the draw of the noise, an integer, default 7):
  base       the log as it is
  urg        ranges beyond 5.6 m reported as no return (a Hokuyo URG's reach)
  laseronly  every odometry reading zero (encoders not read)
  creep      every increment 1 % of the log's (readings nearly constant, as
             odometry in the wrong units would be)
  freeze     odometry readings repeat for ten scans, then resume (a driver that
             stalls, then reports the motion made meanwhile in one step)
  gap        odometry readings missing for ten scans
  wbias      every heading increment 4 % too large (UMBmark Eb = 1.04)
  curve      0.02 rad of heading added per metre driven (unequal wheels)
  noisy      increments with 10 % distance and 5 % + 0.05 rad/m heading noise
  thin       every second scan dropped
"""
import gzip
import math
import os
import random
import sys

VARIANTS = ("base", "urg", "laseronly", "creep", "freeze", "gap", "wbias", "curve", "noisy", "thin")
FAULT_SCANS = 10
URG_RANGE_M = 5.6
CREEP_SCALE = 0.01


def fail(message):
    sys.stderr.write("perturb_carmen_log: %s\n" % message)
    sys.exit(2)


def parse_variant(text):
    """(name, fault start as a fraction of the scans, noise seed)."""
    name, _, where = text.partition("@")
    if name not in VARIANTS:
        fail("unknown variant '%s' (one of: %s)" % (name, ", ".join(VARIANTS)))
    if name == "noisy":
        if where and not where.isdigit():
            fail("'%s': the draw after @ must be a non-negative integer" % text)
        return name, 1.0 / 3.0, int(where) if where else 7
    try:
        fraction = float(where) if where else 1.0 / 3.0
    except ValueError:
        fail("'%s': WHERE must be a number in [0, 1)" % text)
    if not 0 <= fraction < 1:
        fail("'%s': WHERE must be a number in [0, 1)" % text)
    return name, fraction, 7


def read_lines(path):
    opener = gzip.open if path.endswith(".gz") else open
    try:
        with opener(path, "rt") as f:
            return f.read().splitlines()
    except OSError as e:
        fail("%s: %s" % (path, e))


class OdometryRewriter:
    """Re-integrates the raw ODOM increments with a bias or noise."""

    def __init__(self, variant, rng):
        self.variant, self.rng = variant, rng
        self.previous, self.pose = None, None

    def __call__(self, x, y, theta):
        if self.previous is None:
            self.previous, self.pose = (x, y, theta), [x, y, theta]
            return tuple(self.pose)
        px, py, pt = self.previous
        dx, dy = x - px, y - py
        forward = math.cos(pt) * dx + math.sin(pt) * dy
        lateral = -math.sin(pt) * dx + math.cos(pt) * dy
        turn = math.atan2(math.sin(theta - pt), math.cos(theta - pt))
        distance = math.hypot(forward, lateral)
        if self.variant == "wbias":
            turn *= 1.04
        elif self.variant == "creep":
            forward, lateral, turn = CREEP_SCALE * forward, CREEP_SCALE * lateral, CREEP_SCALE * turn
        elif self.variant == "curve":
            turn += 0.02 * distance
        elif self.variant == "noisy":
            forward *= 1 + self.rng.gauss(0, 0.1)
            lateral += self.rng.gauss(0, 0.05) * distance
            turn += self.rng.gauss(0, 0.05 * distance + 0.1 * abs(turn))
        c, s = math.cos(self.pose[2]), math.sin(self.pose[2])
        self.pose = [self.pose[0] + c * forward - s * lateral, self.pose[1] + s * forward + c * lateral,
                     self.pose[2] + turn]
        self.previous = (x, y, theta)
        return tuple(self.pose)


def floats(fields, start, count, where):
    """count numbers from fields[start:]; a clear error naming `where` (FILE:LINE) otherwise."""
    try:
        values = [float(v) for v in fields[start:start + count]]
    except ValueError:
        values = []
    if len(values) != count:
        fail("%s: %s: expected %d numbers from field %d" % (where, fields[0], count, start + 1))
    return values


def scan_ranges(fields, where):
    if len(fields) < 2 or not fields[1].isdigit():
        fail("%s: FLASER: the field after FLASER must be the number of ranges" % where)
    return int(fields[1]), floats(fields, 2, int(fields[1]), where)


def perturb(lines, variant, fraction, seed, path):
    scans = [i for i, l in enumerate(lines) if l.startswith("FLASER")]
    if not scans:
        fail("no FLASER lines: not a CARMEN laser log")
    first = int(len(scans) * fraction)
    fault = (scans[first], scans[min(len(scans) - 1, first + FAULT_SCANS)])
    at = lambda i: "%s:%d" % (path, i + 1)  # noqa: E731 (FILE:LINE of line i)
    no_return = max(max(scan_ranges(lines[i].split(), at(i))[1] or [0]) for i in scans[:50])
    rewrite, frozen, kept_scans, out = OdometryRewriter(variant, random.Random(seed)), None, 0, []
    for index, line in enumerate(lines):
        f = line.split()
        if f and f[0] == "ODOM":
            raw = tuple(floats(f, 1, 3, at(index)))
            pose = raw
            if variant in ("wbias", "curve", "noisy", "creep"):
                pose = rewrite(*raw)
            elif variant == "laseronly":
                pose = (0.0, 0.0, 0.0)
            elif variant == "freeze" and fault[0] <= index <= fault[1]:
                frozen = frozen or raw
                pose = frozen
            elif variant == "gap" and fault[0] <= index <= fault[1]:
                continue
            if pose != raw:  # lines left as they are keep their digits
                f[1:4] = ["%.6f" % v for v in pose]
                line = " ".join(f)
        elif f and f[0] in ("FLASER", "NEFF") and variant == "thin":
            kept_scans += f[0] == "FLASER"
            if kept_scans % 2 == 0:
                continue
        elif f and f[0] == "FLASER" and variant == "urg":
            n, ranges = scan_ranges(f, at(index))
            f[2:2 + n] = ["%g" % (no_return if r > URG_RANGE_M else r) for r in ranges]
            line = " ".join(f)
        out.append(line)
    return out


def main(argv):
    if len(argv) != 4:
        sys.stderr.write(__doc__)
        return 2
    variant, fraction, seed = parse_variant(argv[3])
    if os.path.realpath(argv[2]) == os.path.realpath(argv[1]):
        fail("%s: the output must not overwrite the input" % argv[2])
    lines = perturb(read_lines(argv[1]), variant, fraction, seed, argv[1])
    with open(argv[2], "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
