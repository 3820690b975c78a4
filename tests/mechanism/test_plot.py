"""The torque plot: drawn on given or new axes, its curves and reversal marks there, bad inputs refused."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from geardesign.errors import GearDesignError  # noqa: E402
from geardesign.mechanism.engine import Engine  # noqa: E402
from geardesign.mechanism.plot import plot_torque  # noqa: E402
from geardesign.mechanism.pressure import IndicatorDiagram  # noqa: E402
from geardesign.mechanism.slider_crank import SliderCrank  # noqa: E402


def _result():
    mech = SliderCrank(70, 250, rod_cg_mm=75, piston_mass_kg=2.5, rod_mass_kg=4.7, cylinder_bore_mm=100)
    return Engine(mech, IndicatorDiagram.otto(70, 250, 6.0, peak_pressure_mpa=3.2), 1700, cylinders=2,
                  phases_deg=(0, 540), name="twin").analyse(360)


def test_plot_shows_the_cylinders_the_resultant_and_the_reversals():
    res = _result()
    ax = plot_torque(res)
    labels = [line.get_label() for line in ax.get_lines()]
    assert labels[:3] == ["cylinder 1 (phase 0°)", "cylinder 2 (phase 540°)", "resultant (last journal)"]
    resultant = ax.get_lines()[2]
    np.testing.assert_array_equal(resultant.get_ydata()[:-1], res.torque_nm)
    assert resultant.get_ydata()[-1] == res.torque_nm[0]            # drawn round to the cycle's end
    vertical = [line for line in ax.get_lines() if line.get_linestyle() == ":"]
    assert len(vertical) == res.reversal_angles_deg.size > 0
    assert ax.get_title().startswith("twin\n2-cylinder 4-stroke")
    plt.close(ax.figure)


def test_journals_on_given_axes(tmp_path):
    fig, ax = plt.subplots()
    out = _result().plot(ax=ax, journals=True)
    assert out is ax and any(line.get_label() == "journal 2: M_z2" for line in ax.get_lines())
    fig.savefig(tmp_path / "t.png")
    assert (tmp_path / "t.png").stat().st_size > 1000
    plt.close(fig)


def test_bad_inputs_are_refused():
    with pytest.raises(GearDesignError, match="result must be an EngineTorque"):
        plot_torque([1, 2, 3])
    with pytest.raises(GearDesignError, match="ax must be a matplotlib Axes"):
        plot_torque(_result(), ax="axes")
    with pytest.raises(GearDesignError, match="journals must be True or False"):
        plot_torque(_result(), journals=1)
