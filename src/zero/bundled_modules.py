"""The modules each bundle of ``zero.bundles`` holds, in the order a run finished them: written by
tools/gen_bundled_modules.py.

Generated: do not edit."""

# ruff: noqa
from __future__ import annotations

COMMANDS: dict[str, tuple[str, ...]] = {
    'lint': (
        'zero.hints',
        'zero.record_inits',
        'zero.records',
        'zero.diagnostics',
        'zero.engine',
        'zero.engine.results',
        'zero.errors',
        'zero.cli.exits',
        'zero.patterns',
        'zero.forms',
        'zero.files',
        'zero.output.formats',
        'zero.output',
        'zero.cli.options',
        'zero.engine.selection',
        'zero.engine.config',
        'zero.engine.discovery',
        'zero.engine.project',
        'zero.engine.commands',
        'zero.output.text',
        'zero.cli.run',
    ),
    'check': (
        'zero.catalog',
        'zero.catalog.data',
        'zero.catalog.data.rule_codes',
        'zero.catalog.ranges',
        'zero.catalog.registry',
        'zero.lists',
        'zero.lists.model',
        'zero.lists.encoding',
        'zero.lists.tokenizer',
        'zero.catalog.evidence',
        'zero.catalog.ids',
        'zero.catalog.values',
        'zero.rules.base',
        'zero.catalog.data.rules_declared',
        'zero.rules.syntax',
        'zero.rules.elements',
        'zero.rules.files',
        'zero.rules.meaning',
        'zero.rules.registry',
        'zero.catalog.condition_helpers',
        'zero.catalog.data.startup_facts',
        'zero.rules.startup',
        'zero.rules.suppress',
        'zero.rules.update',
        'zero.rules.families',
        'zero.rules.funnel',
        'zero.rules.lists',
        'zero.rules',
        'zero.engine.lint',
        'zero.engine.parallel',
        'zero.catalog.data.table',
        'zero.catalog.data.seeds',
        'zero.pattern_codes',
        'zero.catalog.data.prose_compiled',
    ),
    'table-axis': (
        'zero.catalog.data.table_axis',
    ),
    'kind-axis': (
        'zero.catalog.data.specs_axis',
        'zero.catalog.data.ranges_compiled_axis',
        'zero.catalog.data.startup_compiled_axis',
    ),
    'table-chan': (
        'zero.catalog.data.table_chan',
    ),
    'kind-chan': (
        'zero.catalog.data.specs_chan',
        'zero.catalog.data.ranges_compiled_chan',
        'zero.catalog.data.startup_compiled_chan',
    ),
    'table-clmp': (
        'zero.catalog.data.table_clmp',
    ),
    'kind-clmp': (
        'zero.catalog.data.specs_clmp',
        'zero.catalog.data.ranges_compiled_clmp',
    ),
    'table-cmld': (
        'zero.catalog.data.table_cmld',
    ),
    'kind-cmld': (
        'zero.catalog.data.specs_cmld',
    ),
    'table-comp': (
        'zero.catalog.data.table_comp',
    ),
    'kind-comp': (
        'zero.catalog.data.specs_comp',
        'zero.catalog.data.ranges_compiled_comp',
        'zero.catalog.data.startup_compiled_comp',
    ),
    'table-extv': (
        'zero.catalog.data.table_extv',
    ),
    'kind-extv': (
        'zero.catalog.data.specs_extv',
        'zero.catalog.data.ranges_compiled_extv',
        'zero.catalog.data.startup_compiled_extv',
    ),
    'table-hwcf': (
        'zero.catalog.data.table_hwcf',
    ),
    'kind-hwcf': (
        'zero.catalog.data.specs_hwcf',
    ),
    'table-manu': (
        'zero.catalog.data.table_manu',
    ),
    'kind-manu': (
        'zero.catalog.data.specs_manu',
        'zero.catalog.data.ranges_compiled_manu',
    ),
    'table-rtcf': (
        'zero.catalog.data.table_rtcf',
    ),
    'kind-rtcf': (
        'zero.catalog.data.specs_rtcf',
        'zero.catalog.data.ranges_compiled_rtcf',
        'zero.catalog.data.startup_compiled_rtcf',
    ),
    'table-seco': (
        'zero.catalog.data.table_seco',
    ),
    'kind-seco': (
        'zero.catalog.data.specs_seco',
        'zero.catalog.data.ranges_compiled_seco',
    ),
    'table-stup': (
        'zero.catalog.data.table_stup',
    ),
    'kind-stup': (
        'zero.catalog.data.specs_stup',
        'zero.catalog.data.ranges_compiled_stup',
    ),
    'table-tool': (
        'zero.catalog.data.table_tool',
    ),
    'kind-tool': (
        'zero.catalog.data.specs_tool',
        'zero.catalog.data.ranges_compiled_tool',
    ),
    'table-volc': (
        'zero.catalog.data.table_volc',
    ),
    'kind-volc': (
        'zero.catalog.data.specs_volc',
        'zero.catalog.data.ranges_compiled_volc',
    ),
    'table-zero': (
        'zero.catalog.data.table_zero',
    ),
    'kind-zero': (
        'zero.catalog.data.specs_zero',
        'zero.catalog.data.ranges_compiled_zero',
        'zero.catalog.data.startup_compiled_zero',
    ),
}
