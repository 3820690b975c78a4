"""Tooth profiles as the cutter generates them (issue 14 builds the meshing drawing and the exports on these)."""
