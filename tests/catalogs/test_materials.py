"""The ISO 6336-5 material tables (geardesign.catalogs.materials): every line cited, within its own ranges, and
the lines that ISO/TR 6336-30:2017 example 1 and the material's own docstring name."""
import pandas as pd

from geardesign.catalogs.materials import HARDNESS_SCALES, QUALITIES, material_group_lines, named_materials


def test_every_line_has_a_source_a_quality_a_scale_and_an_ordered_hardness_range():
    lines = material_group_lines()
    assert len(lines) > 20 and lines.source.str.len().min() > 10
    assert set(lines.quality) <= set(QUALITIES) and set(lines.stress) == {"contact", "bending"}
    assert set(lines.hardness_scale) <= set(HARDNESS_SCALES)
    assert (lines.hardness_min < lines.hardness_max).all()
    # σ_lim = A x + B stays positive over the line's hardness range (a transcription slip would not)
    low = lines.A * lines.hardness_min + lines.B
    high = lines.A * lines.hardness_max + lines.B
    assert (low > 0).all() and (high > 0).all()


def test_the_qualities_are_ordered_ml_mq_me():
    # ISO 6336-5: ML <= MQ <= ME at every hardness of a group's line (the grades of material quality)
    lines = material_group_lines()
    for (group, stress), rows in lines.groupby(["group", "stress"]):
        by_q = {q: r.iloc[0] for q, r in rows.groupby("quality")}
        if not {"ML", "MQ", "ME"} <= set(by_q):
            continue
        x = max(r.hardness_min for r in by_q.values()), min(r.hardness_max for r in by_q.values())
        for h in x:
            vals = [by_q[q].A * h + by_q[q].B for q in ("ML", "MQ", "ME")]
            assert vals[0] <= vals[1] + 1e-9 <= vals[2] + 2e-9, (group, stress, h, vals)


def test_named_steels():
    named = named_materials()
    assert isinstance(named, pd.DataFrame) and named.index.is_unique
    row = named.loc["18CrNiMo7-6"]          # the case-hardened steel of ISO/TR 6336-30 example 1
    assert row.group == "Eh" and row.E_mpa == 206000 and row.nu == 0.3
    assert named.loc["42CrMo4", "group"] == "V_alloy"
    assert set(named.group) <= set(material_group_lines().group)
