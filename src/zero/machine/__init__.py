"""A machine as its start-up list assembles it: ``model`` (the lists, channels and axes,
read and evaluated) and ``limits`` (soft limits per work offset, the IP247 rule)."""
