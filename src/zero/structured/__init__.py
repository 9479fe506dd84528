"""The structured forms of a list (YAML, TOML, JSON) and their JSON Schema.

``tree`` (list ↔ tree of leaves with comments and the ``_zero`` layout record),
``common`` (what the three formats share), ``yaml``/``toml``/``json`` (one reader and
one writer each), ``formats`` (format by name, read/write any of them), ``schema``
(``zero schema``).
"""
