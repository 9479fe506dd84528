"""Output: findings and results as people and CI systems read them.

``text`` (the report for people, statistics, progress), ``formats`` (JSON, concise,
GitHub, GitLab, JUnit, SARIF), ``tables`` (``zero diff`` and ``zero limits``),
``docs`` (rule explanations and parameter facts).
"""

# The report formats of `zero lint`, named once (the renderers in ``formats`` are held to this list
# where they are defined; the lean command line reads it without importing them). The streamed
# ones are written finding by finding, as the results come.
OUTPUT_FORMATS = ("text", "concise", "json", "github", "gitlab", "junit", "sarif")
STREAMED_FORMATS = ("text", "json", "concise", "github")
