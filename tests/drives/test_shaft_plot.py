"""plot_shaft: three diagrams holding the analysis' own curves, a PNG written whole, never over a file
without overwrite, and a wrong argument named."""
import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from geardesign.drives.shaft_beam import ShaftLoad, ShaftModel, analyse_shaft  # noqa: E402
from geardesign.drives.shaft_plot import plot_shaft  # noqa: E402
from geardesign.errors import GearDesignError  # noqa: E402


def _analysis():
    return analyse_shaft(ShaftModel([(40, 30), (120, 40), (40, 30)], [20, 180],
                                    [ShaftLoad(100, fy_n=-2000, fz_n=800, torque_nm=60),
                                     ShaftLoad(200, fz_n=300, torque_nm=-60)]))


def test_the_diagrams_are_the_analysis_curves():
    a = _analysis()
    fig = plot_shaft(a)
    moment, torque, deflection = fig.axes[:3]
    lines = {ln.get_label(): ln for ln in moment.get_lines()}
    np.testing.assert_array_equal(lines["M resultant"].get_ydata(), a.diagrams["M_nm"].to_numpy())
    np.testing.assert_array_equal(torque.get_lines()[0].get_ydata(), a.diagrams["T_nm"].to_numpy())
    w = {ln.get_label(): ln for ln in deflection.get_lines()}["w resultant"].get_ydata()
    np.testing.assert_allclose(w, 1000 * a.diagrams["w_mm"].to_numpy(), rtol=1e-15)   # µm
    assert "deflection" in deflection.get_ylabel() and "N·m" in moment.get_ylabel()
    import matplotlib.pyplot as plt
    plt.close(fig)


def test_png_written_and_never_overwritten(tmp_path):
    a = _analysis()
    png = tmp_path / "shaft.png"
    plot_shaft(a, png)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    before = png.read_bytes()
    with pytest.raises(GearDesignError, match="--overwrite"):
        plot_shaft(a, png)
    assert png.read_bytes() == before
    plot_shaft(a, png, overwrite=True)
    assert list(tmp_path.iterdir()) == [png]       # no temporary file left behind


def test_not_an_analysis():
    with pytest.raises(GearDesignError, match="ShaftAnalysis"):
        plot_shaft("shaft.png")
