#!/usr/bin/env python3
"""Checks a `cig cosim --trace` FST (converted by gtkwave's fst2vcd) and its save file FILE.gtkw.

  check_trace.py --vcd W.vcd --gtkw W.fst.gtkw --unit 1ns --first T0 --last-from T1 --last-to T2

* the VCD's timescale is --unit, its first timestamp is --first (A x period: the window's first
  rising edge) and its last one lies in [--last-from, --last-to] (B x period .. B x period +
  period - 1: the window's last cycle);
* every signal the save file names is a variable of the trace, named as gtkwave names it (scopes
  joined by '.', a vector's range "[MSB:LSB]" after its name, a one-bit range "[0:0]" as "[0]"),
  and it names at least one;
* its groups open and close in pairs ("@800200" / "@1000200" flags before "-NAME").
Prints one summary line; exits 1 with the reason on the first failure.
"""
import argparse
import re
import sys


def fail(why):
    print("check_trace: " + why)
    sys.exit(1)


def read_vcd(path):
    """Variables (gtkwave names), the timescale, the first and the last timestamp."""
    names, scopes, timescale, first, last = set(), [], None, None, None
    in_timescale = False
    with open(path, encoding="utf-8", errors="replace") as f:
        in_defs = True
        for line in f:
            if in_defs:
                t = line.split()
                if not t:
                    continue
                if in_timescale:
                    if t[0] != "$end":
                        timescale = "".join(x for x in t if x != "$end")
                    in_timescale = "$end" not in t
                elif t[0] == "$timescale":
                    rest = [x for x in t[1:] if x != "$end"]
                    if rest:
                        timescale = "".join(rest)
                    in_timescale = "$end" not in t
                elif t[0] == "$scope":
                    scopes.append(t[2])
                elif t[0] == "$upscope":
                    scopes.pop()
                elif t[0] == "$var":
                    kind, name, rng = t[1], t[4], t[5] if t[5] != "$end" else ""
                    m = re.fullmatch(r"\[(\d+):(\d+)\]", rng)
                    if kind in ("parameter", "integer", "int", "shortint", "longint", "byte"):
                        rng = ""
                    elif m and m.group(1) == m.group(2):
                        rng = "[%s]" % m.group(1)
                    names.add(".".join(scopes + [name]) + rng)
                elif t[0] == "$enddefinitions":
                    in_defs = False
            elif line.startswith("#"):
                stamp = int(line[1:])
                if first is None:
                    first = stamp
                last = stamp
    return names, timescale, first, last


def read_gtkw(path):
    """The signals a save file names, and whether its groups pair up."""
    signals, open_groups, flags = [], [], 0
    with open(path, encoding="utf-8") as f:
        for raw in f:
            line = raw.rstrip("\n")
            if not line or line.startswith("[") or line.startswith("*"):
                continue
            if line.startswith("@"):
                flags = int(line[1:], 16)
            elif line.startswith("-"):
                if flags & 0x800000:
                    open_groups.append(line[1:])
                elif flags & 0x1000000:
                    if not open_groups or open_groups.pop() != line[1:]:
                        fail("%s: group end '%s' does not close the open group" % (path, line[1:]))
            else:
                signals.append(line)
    if open_groups:
        fail("%s: groups left open: %s" % (path, open_groups))
    return signals


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--vcd", required=True)
    ap.add_argument("--gtkw", required=True)
    ap.add_argument("--unit", required=True)
    ap.add_argument("--first", type=int, required=True)
    ap.add_argument("--last-from", type=int, required=True)
    ap.add_argument("--last-to", type=int, required=True)
    a = ap.parse_args()
    names, timescale, first, last = read_vcd(a.vcd)
    if timescale != a.unit:
        fail("timescale %s, expected %s" % (timescale, a.unit))
    if first != a.first:
        fail("first timestamp %s, expected %d" % (first, a.first))
    if last is None or not a.last_from <= last <= a.last_to:
        fail("last timestamp %s, expected %d..%d" % (last, a.last_from, a.last_to))
    signals = read_gtkw(a.gtkw)
    if not signals:
        fail("%s names no signal" % a.gtkw)
    missing = [s for s in signals if s not in names]
    if missing:
        fail("%s names %d signal(s) the trace does not have, e.g. %s" % (a.gtkw, len(missing), missing[:3]))
    print("check_trace: %s: timescale %s, time %d..%d, %d variables; %s: %d signals, all in the trace"
          % (a.vcd, timescale, first, last, len(names), a.gtkw, len(signals)))


if __name__ == "__main__":
    main()
