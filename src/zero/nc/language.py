"""The words of the ISG NC language zero knows, as facts with their sources.

Sources: the vendor's programming manual (TF5200 programming manual, "[PROG]"), the vendor's
diagnosis manual, and the grammar of the vendor's public VS Code extension
(``isg-stuttgart/vscode-isg-cnc``: its PEG grammar ``server/parserGenerating/ncGrammar.pegjs``
and its TextMate grammar ``isg-cnc.tmLanguage.json``). Only facts are carried here (which
keywords exist and how blocks are built), never their code.

A block is: an optional skip mark (``/``, ``/1`` … ``/10``), an optional main-block mark
(``:``), an optional block number ``N<n>`` (a label when followed by ``:``) or a label
``[NAME]``, then address words (a letter and a value: ``X12.5``, ``XP1``, ``XV.L.A``,
``X[P1+2]``, ``X=…``), ``$``-control keywords, ``#``-commands, variable assignments
(``V.L.NAME = …``, ``P1 = …``), subprogram calls (``L name``, ``LL name``,
``L CYCLE [NAME=…]``). Comments: ``( … )`` (also unclosed), ``; …``, and
``#COMMENT BEGIN`` … ``#COMMENT END``. A line ending in ``\\`` continues the block.
Program parts: ``%L name`` (a local subprogram), ``%name`` (the main program).
"""

from __future__ import annotations

# The control keywords (`$`): the extension's TextMate grammar lists exactly these.
DOLLAR_KEYWORDS = frozenset({
    "IF", "ELSEIF", "ELSE", "ENDIF", "GOTO", "SWITCH", "CASE", "DEFAULT", "ENDSWITCH",
    "WHILE", "ENDWHILE", "FOR", "ENDFOR", "DO", "ENDDO", "REPEAT", "UNTIL", "BREAK", "CONTINUE",
})

# Opening keyword → the keyword that closes it ([PROG] control structures).
OPENERS = {"IF": "ENDIF", "WHILE": "ENDWHILE", "FOR": "ENDFOR", "SWITCH": "ENDSWITCH", "DO": "ENDDO",
           "REPEAT": "UNTIL"}
CLOSERS = {v: k for k, v in OPENERS.items()}
LOOPS = frozenset({"WHILE", "FOR", "DO", "REPEAT"})
BRANCHES = {"ELSEIF": "IF", "ELSE": "IF", "CASE": "SWITCH", "DEFAULT": "SWITCH"}

# The first word of every #-command the extension's TextMate grammar lists, plus the commands of
# the programming manual zero reads (#MACHINE DATA, #OPTIONAL EXECUTION, #PARAMETER, #MIRROR).
HASH_COMMANDS = frozenset({
    "ACHSE", "ACHSTAUSCH", "ACS", "ADD", "AKIMA", "ANG", "AX", "BACKWARD", "BLOCKSEARCH", "CACHE",
    "CALL", "CAX", "CAXTRACK", "CHANNEL", "CHF", "CHR", "CLEAR", "COMMAND", "COMMENT", "CONTOUR",
    "CONTROL", "CORNER", "CS", "CYL", "DEL", "DELETE", "DISABLE", "DISTANCE", "DRIVE", "DYNAMIC",
    "DYN_WEIGHT", "ECS", "EDGE", "EDM", "ELSE", "ENABLE", "ENDIF", "ENDVAR", "ERROR", "EXPL", "EXPORT",
    "FACE", "FGROUP", "FILE", "FILTER", "FLUSH", "FRC", "FREE", "GANTRY", "GET", "HANDWHEEL", "HSC",
    "IDENT", "IF", "INFO", "INIT", "JOG", "KIN", "LOAD", "LOCK", "MACHINE", "MAIN", "MANUAL", "MCS",
    "MEAS", "MICROJOINT", "MIRROR", "MSG", "NIBBLE", "OPTIONAL", "OTC", "OVERRIDE", "PARAMETER",
    "PRESET", "PSET", "PTP", "PUNCH", "PUT", "RND", "ROTATION", "RT", "RTCP", "SAVE", "SCALE",
    "SEGMENTATION", "SET", "SIGNAL", "SINGLE", "SLOPE", "SPLINE", "START", "STROKE", "SUPPRESS",
    "TANGFEED", "TIME", "TIMER", "TLC", "TOOL", "TRACK", "TRAFO", "TRANSVELMIN", "TRC", "UNLOCK", "VAR",
    "VECTOR", "VOLCOMP", "WAIT", "WCS",
})
# Families of #-commands named by a prefix (the vendor's own test program uses #MC_MovePath).
HASH_PREFIXES = ("MC_",)

# #-commands after which zero cannot follow positions until they are switched off: kinematic
# transformations, coordinate systems, and transformations of the programmed contour.
TRANSFORMS = frozenset({"TRAFO", "CS", "ACS", "RTCP", "ROTATION", "CYL", "FACE", "SCALE", "MIRROR",
                        "TRACK", "KIN"})

# Address letters of the language ([PROG]; the extension's grammar: a letter and a number).
ADDRESS_LETTERS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZ")
# Axis letters zero assumes when no machine names the channel's axes.
DEFAULT_AXES = ("X", "Y", "Z", "A", "B", "C", "U", "V", "W")

# Variable families `V.<family>.` ([PROG] variables; the extension's grammar).
VARIABLE_FAMILIES = frozenset({"A", "SPDL", "G", "P", "S", "L", "E", "TOOL", "TLM", "CYC", "I", "CD"})
# Of these, the ones a program assigns itself (the others belong to the controller, the PLC or a cycle).
OWN_VARIABLES = frozenset({"P", "S", "L", "CYC"})

# Words of expressions and axis-specific commands that may appear inside `[ … ]` or after `=`.
FUNCTIONS = frozenset({"ABS", "SQR", "SQRT", "EXP", "LN", "DEXP", "LOG", "SIN", "COS", "TAN", "COT",
                       "ASIN", "ACOS", "ATAN", "ATAN2", "ACOT", "INT", "FRACT", "CEIL", "ROUND", "FLOOR",
                       "INV", "NOT", "MOD", "XOR", "TRUE", "FALSE", "PI", "EXIST", "IS_STRING"})

# G codes whose axis words are no target positions ([PROG]): dwell, homing, G92 coordinate preset,
# G98/G99 programmed soft limits.
G_NOT_TARGETS = frozenset({4, 74, 92, 98, 99})
# G codes zero follows: motion, plane, units, dimensions, offsets, circle-centre mode, mirroring
# (G20-G23: counted as not evaluated while active), diameter programming (G51/G52).
G_FOLLOWED = frozenset({0, 1, 2, 3, 17, 18, 19, 20, 21, 22, 23, 51, 52, 53, 54, 55, 56, 57, 58, 59, 70, 71, 90,
                        91, 159, 161, 162})
# G codes that leave programmed positions alone ([PROG] "Meaning of G functions", P-CHAN-00063):
# acceleration and exact stop, feed and speed modes, tool radius compensation and its variants,
# corner deceleration, precontrol.
G_STATE = frozenset({8, 9, 10, 11, 12, 13, 40, 41, 42, 60, 61, 93, 94, 95, 96, 97, 135, 137, 138, 139, 140,
                     141, 164, 165, 236, 237, 238, 239})

# Kernel error numbers.
SOFT_LIMIT_ERRORS = "P-ERR-120002 or P-ERR-120003"  # block beyond a soft limit in path preparation
SOFT_LIMIT_SOURCE = "https://infosys.beckhoff.com/content/1033/swlimit/15311258251.html"
