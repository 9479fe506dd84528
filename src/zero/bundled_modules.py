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
    'kind-axis': (
        'zero.catalog.data.specs_axis',
        'zero.catalog.data.ranges_compiled_axis',
        'zero.catalog.data.startup_compiled_axis',
    ),
    'kind-chan': (
        'zero.catalog.data.specs_chan',
        'zero.catalog.data.ranges_compiled_chan',
        'zero.catalog.data.startup_compiled_chan',
    ),
    'kind-clmp': (
        'zero.catalog.data.specs_clmp',
        'zero.catalog.data.ranges_compiled_clmp',
    ),
    'kind-cmld': (
        'zero.catalog.data.specs_cmld',
    ),
    'kind-comp': (
        'zero.catalog.data.specs_comp',
        'zero.catalog.data.ranges_compiled_comp',
        'zero.catalog.data.startup_compiled_comp',
    ),
    'kind-extv': (
        'zero.catalog.data.specs_extv',
        'zero.catalog.data.ranges_compiled_extv',
        'zero.catalog.data.startup_compiled_extv',
    ),
    'kind-hwcf': (
        'zero.catalog.data.specs_hwcf',
    ),
    'kind-manu': (
        'zero.catalog.data.specs_manu',
        'zero.catalog.data.ranges_compiled_manu',
    ),
    'kind-rtcf': (
        'zero.catalog.data.specs_rtcf',
        'zero.catalog.data.ranges_compiled_rtcf',
        'zero.catalog.data.startup_compiled_rtcf',
    ),
    'kind-seco': (
        'zero.catalog.data.specs_seco',
        'zero.catalog.data.ranges_compiled_seco',
    ),
    'kind-stup': (
        'zero.catalog.data.specs_stup',
        'zero.catalog.data.ranges_compiled_stup',
    ),
    'kind-tool': (
        'zero.catalog.data.specs_tool',
        'zero.catalog.data.ranges_compiled_tool',
    ),
    'kind-volc': (
        'zero.catalog.data.specs_volc',
        'zero.catalog.data.ranges_compiled_volc',
    ),
    'kind-zero': (
        'zero.catalog.data.specs_zero',
        'zero.catalog.data.ranges_compiled_zero',
        'zero.catalog.data.startup_compiled_zero',
    ),
}
