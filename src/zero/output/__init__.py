"""Output: findings and results as people and CI systems read them.

``text`` (the report for people, statistics, progress), ``formats`` (one module per
machine-readable format, and their registry), ``tables`` (``zero diff`` and ``zero limits``),
``docs`` (rule explanations and parameter facts).
"""

# The report formats of `zero lint` are declared once, in zero.output.formats (which imports no emitter).
from zero.output.formats import OUTPUT_FORMATS, STREAMED_FORMATS

__all__ = ["OUTPUT_FORMATS", "STREAMED_FORMATS"]
