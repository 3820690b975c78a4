"""The benchmarks' one timer: CPU time of this process per call (time.process_time), the best of ``repeat``
rounds of ``number`` calls. On a machine shared with other jobs the wall clock of a call drifts by 2-4x from one
round to the next, its CPU time much less (the code is single-threaded); the least round is the least disturbed."""
import time


def best(fn, repeat=5, number=20) -> float:
    """Seconds of CPU per call of ``fn()``: the best of ``repeat`` rounds of ``number`` calls."""
    times = []
    for _ in range(repeat):
        t = time.process_time()
        for _ in range(number):
            fn()
        times.append((time.process_time() - t) / number)
    return min(times)
