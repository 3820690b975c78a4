"""The geardesign test suite. Its folders mirror the package: tests/gears/test_geometry.py tests
geardesign/gears/geometry.py, tests/cli/test_shift.py the `geardesign shift` command, and so on.

At the top level: the suites that cut across the package (golden data, extremes against mpmath,
property tests, fuzzing, doctests), the tests of the top-level modules (files, validate), and the
shared helpers the test modules import as ``tests.<name>``: strategies (hypothesis designs),
reference_mp (50-digit reference geometry), mp_formulas, scene_files, fuzzcases with fuzzsurfaces,
fuzzstrength (the load-capacity targets) and fuzzrecheck (also used by tools/fuzz.py) and data/ (golden
values with their sources).
"""
