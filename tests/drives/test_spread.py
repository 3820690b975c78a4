"""Solved options spread over a cluster with one cache (geardesign.drives.spread): without a client it is the
kind's own solve_many; a worker's chunk, run here as a worker runs it, solves exactly the pairs the caller had
not solved and hands them back to join the caller's cache (so two workers never solve one pair twice, and a
cluster makes the serial run's solves; the cluster itself: tests/test_parallel.py)."""
import geardesign as gd
from geardesign.drives.spread import _solve_chunk, solve_spread
from geardesign.drives.stage_kinds import kind_of
from geardesign.drives.stage_kinds.gear import clear_shift_cache

STAGE = gd.GearStage(3, z1_range=(19, 20), ratio_range=(3, 3.2))
OPTIONS = [{"z1": 19, "z2": 59, "ratio": 59 / 19}, {"z1": 20, "z2": 62, "ratio": 3.1},
           {"z1": 19, "z2": 60, "ratio": 60 / 19}]


def test_without_a_client_it_is_the_kinds_solve_many():
    kind = kind_of(STAGE)
    clear_shift_cache()
    got = solve_spread(None, kind, STAGE, OPTIONS, "min_size", [None] * 3)
    clear_shift_cache()
    want = kind.solve_many(STAGE, OPTIONS, "min_size", [None] * 3)
    assert [(s["x1"], s["x2"], s["a_w"]) for s in got] == [(s["x1"], s["x2"], s["a_w"]) for s in want]


def test_a_chunk_solves_only_what_the_caller_had_not_and_hands_it_back():
    kind = kind_of(STAGE)
    clear_shift_cache()
    kind.solve_many(STAGE, OPTIONS[:1], "min_size", [None])          # the caller has solved 19/59
    known = kind.solved_for(OPTIONS)
    assert [k[1:3] for k in known] == [(19, 59)]
    before = kind.solve_count()
    sols, solved = _solve_chunk(kind, STAGE, "min_size", (OPTIONS, [None] * 3, known))
    assert sorted(k[1:3] for k in solved) == [(19, 60), (20, 62)]   # the two it had not
    after_chunk = kind.solve_count()
    kind.absorb(solved)                                              # joins the caller's cache, counted once each
    # (run in this process the chunk's own solves count here too; on a worker only the absorbed ones do)
    assert after_chunk - before == 2 and kind.solve_count() - after_chunk == 2
    again = kind.solve_many(STAGE, OPTIONS, "min_size", [None] * 3)  # nothing left to solve
    assert [s["x1"] for s in again] == [s["x1"] for s in sols]
