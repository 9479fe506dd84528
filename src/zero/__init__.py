"""zero: lint, diff and convert the ASCII parameter lists of the ISG kernel CNC controller."""

__version__ = "0.1.0"
