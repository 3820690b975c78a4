"""Tests of geardesign.cli (one module per subcommand)."""
