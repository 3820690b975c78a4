"""Sensitivity studies: sweeps of one or two inputs, local sensitivities and their plots."""
