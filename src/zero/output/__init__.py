"""Output: findings and results as people and CI systems read them.

``text`` (the report for people, statistics, progress), ``formats`` (JSON, concise,
GitHub, GitLab, JUnit, SARIF), ``tables`` (``zero diff`` and ``zero limits``),
``docs`` (rule explanations and parameter facts).
"""

# The report formats of `zero lint`, named once (the renderers in ``formats`` are held to this list
# where they are defined; the lean command line reads it without importing them). The streamed
# ones are written finding by finding, as the results come.
OUTPUT_FORMATS = ("text", "full", "concise", "grouped", "json", "json-lines", "github", "gitlab", "azure", "junit",
                  "sarif", "rdjson", "pylint")
STREAMED_FORMATS = ("text", "full", "json", "concise", "github", "json-lines", "pylint", "azure", "grouped")
