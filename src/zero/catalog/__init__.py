"""The catalogue: what zero knows about every parameter, as data passed in.

``registry`` (the table of 1,766 parameters and its look-ups), ``paramdesc`` (the
vendor's ``CncParaDesc.xml`` reader), ``ranges`` (formal ranges, parsed and
evaluated), ``values`` (an entry's value as the controller reads it, and a list's
values with defaults), ``ids`` (well-known IDs, units and G codes).
"""
