"""Profile shifts: the problem, its objectives, one module per method, conflicts, the region, atlases
and tooth counts. Built on :mod:`geardesign.gears`."""
