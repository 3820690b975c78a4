"""One local Dask cluster of two processes per test module (a start costs a second or two), and the
bit-for-bit comparison of two tables the cluster tests share."""
import numpy as np
import pandas as pd
import pytest

from geardesign import parallel


@pytest.fixture(scope="module")
def client():
    with parallel.cluster(workers=2) as c:
        yield c


def assert_same_bits(a: pd.DataFrame, b: pd.DataFrame) -> None:
    """Same columns, dtypes, index and values; floats compared as their 64-bit patterns (so -0.0
    differs from 0.0 and NaN equals NaN only when the bits agree)."""
    assert list(a.columns) == list(b.columns)
    assert a.dtypes.tolist() == b.dtypes.tolist()
    assert a.index.equals(b.index)
    for col in a.columns:
        x, y = a[col].to_numpy(), b[col].to_numpy()
        if x.dtype.kind == "f":
            assert np.array_equal(x.view(np.int64), y.view(np.int64)), col
        else:
            assert (x == y).all() or all(u == v or (u != u and v != v) for u, v in zip(x, y)), col
