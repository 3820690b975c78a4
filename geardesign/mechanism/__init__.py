"""The slider-crank mechanism of a piston engine: exact kinematics, kinetostatics (the force in every joint and
the balancing torque, also by virtual power), the gas force from an indicator diagram, and the crankshaft's torque
over the working cycle of several cylinders with their firing phases (journal and crank-pin torques, unevenness,
the flywheel's coefficient of fluctuation).

Imports only :mod:`geardesign.errors`, :mod:`geardesign.validate` and :mod:`geardesign.results` from above it:
the load spectra and the service life that count this torque sit with the strength model (:mod:`geardesign.gears`).
"""
