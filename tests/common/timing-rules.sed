# SPDX-License-Identifier: Apache-2.0
# The times lutkit prints, blanked before two runs of the same command are compared: they differ
# from run to run and between editions, the rest of a report may not. One list, read by both edition
# tests: tests/windows/run.sh as a sed script (sed -E -f), tests/web/test_same_bytes.py rule by rule
# (Python's re.sub, each line of the text on its own). So each rule is `s#REGEX#REPLACEMENT#g` in
# the syntax both share: POSIX extended regexes with \b, no '#' inside, no & or back-references in
# the replacement, nothing that spans a line.
#
# A duration: "0.25 s", "12 ms", "3.1e-05 s" (and "12ms").
s#[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? ?ms\b#T ms#g
s#[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)? s\b#T s#g
# A step shorter than the clock's tick measures 0 s, and a time of 0 is not printed
# (ErrorStats::str): whether the time is there is the clock's doing, not lutkit's.
s#, T ms##g
# match's time line: "time     1.2 s (fit 0.333, LUT 0.00169, measures 0.0205)".
s#^time .*$#time T#g
# A batch's rate, and --json's seconds.
s#[0-9.]+ files/s#T files/s#g
s#"seconds": [0-9.e+-]+#"seconds": T#g
