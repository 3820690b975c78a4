"""Tests of geardesign.drives.chain."""

# Seed 002 (the brake test stand course work, docs/references.md): T1 = 380 N·m at 120 rpm, u = 1, z1 = 13,
# K_e = 2.148, [p] = 29 MPa, one or two strands. Shared by the chain and sprocket tests.
SEED = dict(torque_nm=380, n1_rpm=120, ratio=1, z1=13, k_e=2.148, allowable_pressure_mpa=29, strands=(1, 2))
