"""Tooth profiles as the cutter generates them (rack for external gears, shaper for rings), the meshing
drawing, its diagrams and the DXF/SVG/CSV exports."""
