"""Output: findings and results as people and CI systems read them.

``text`` (the report for people, statistics, progress), ``formats`` (JSON, concise,
GitHub, GitLab, JUnit, SARIF), ``tables`` (``zero diff`` and ``zero limits``),
``docs`` (rule explanations and parameter facts).
"""
