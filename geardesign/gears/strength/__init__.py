"""Load capacity of cylindrical gears after ISO 6336 (contact and tooth-root strength)."""
