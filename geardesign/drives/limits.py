"""The drive's objectives and every limit on its inputs and on the work of its search (one place each)."""
from __future__ import annotations

__all__ = ["OBJECTIVES", "STAGES_MAX", "COMBINATIONS_MAX", "CANDIDATES_MAX", "TOP_MAX", "TOTAL_RATIO_RANGE",
           "RATIO_TOL_RANGE", "SPEED_RANGE_RPM", "POWER_RANGE_KW", "TORQUE_RANGE_NM", "MARGIN_TOL", "SHIFT_CACHE",
           "INFEASIBLE_SHOWN", "LOAD_BOUNDS_MAX", "LOAD_CELL", "COMBINATION_BLOCK", "PLAIN_DESIGNS_MAX", "PRUNE_GROWTH", "SIZING_TRIES", "LOOK_AHEAD",
           "MARGIN_AHEAD"]

OBJECTIVES = ("min_size", "min_mass", "max_margin")
STAGES_MAX = 6                    # stages in one drive
COMBINATIONS_MAX = 4_000_000      # ratio combinations (one option per stage) held at once (~100 MB for 3 stages)
COMBINATION_BLOCK = 4_000_000     # (partial product, option) pairs tested at once while the split is built (~40 MB)
CANDIDATES_MAX = 2_000_000        # designs evaluated at once: combinations × chain catalog rows
PLAIN_DESIGNS_MAX = 1_000_000     # designs of a split enumerated whole; beyond, under a cost limit (drives/pruning.py)
PRUNE_GROWTH = 1.25               # the cost limit of a pruned split is raised by this factor until the list is complete
TOP_MAX = 1000                    # alternatives listed
TOTAL_RATIO_RANGE = (1e-3, 1e5)
RATIO_TOL_RANGE = (0.0, 0.5)
SPEED_RANGE_RPM = (0.1, 100_000.0)
POWER_RANGE_KW = (1e-6, 1e5)
TORQUE_RANGE_NM = (1e-3, 1e9)
MARGIN_TOL = 1e-9                 # the exact shift solver holds its checks to 1e-9: such margins hold
SHIFT_CACHE = 4096                # solved tooth pairs kept between calls (each ~2-6 ms to solve)
INFEASIBLE_SHOWN = 5              # closest failing designs listed after the feasible ones
LOAD_BOUNDS_MAX = 20_000          # (option, input flow) bounds of a stage sized by load; beyond, its load-free bound
LOAD_CELL = 1.05                  # a stage whose cost grows with its load is bounded per option and torque cell of
                                  # this ratio (its cost at the cell's least torque): designs of a cell within 5 %
                                  # (three sized stages, u = 70: 15-17 s CPU at 1.05, 21 s at 1.1, 22 s at 1.03;
                                  # the conveyor of issue 35: 23 s at 1.05, 15 s at 1.1; shared machine)
SIZING_TRIES = 8                  # sized candidates re-solved for their own shifts before a tooth pair is given up
LOOK_AHEAD = 16                   # groups of the branch and bound whose options are solved together (a pair's
                                  # strength sizing shares one vectorised call, ~1 ms of fixed cost per call);
                                  # at most 15 solved past the stop (none in the sized benchmark drive)
MARGIN_AHEAD = 256                # groups whose max_margin shifts are solved in one batch (~3 ms fixed, 0.07 ms a
                                  # pair: 256 take ~20 ms, as much as seven pairs solved one by one)
BATCH_BLOCK = 16_000              # designs per evaluation of a chain stage's checks: a drive's 10⁵-10⁶ designs in
                                  # blocks whose temporaries stay in the caches (491 319 designs: 0.165 s whole,
                                  # 0.115 s in blocks; the chain's formulas are elementwise, so the same values)
