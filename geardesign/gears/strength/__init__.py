"""ISO 6336 load capacity of spur and helical gears (parts 1, 2, 3 and 5)."""
