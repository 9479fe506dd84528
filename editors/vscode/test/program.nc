; SYNTAX TEST "source.isg-nc" "NC programs: lines of fixtures/programs"
%L good
; <- punctuation.definition.program.isg-nc
;^ keyword.other.program.isg-nc
;  ^^^^ entity.name.function.program.isg-nc
; a program zero reads past: cycles, control structures, messages, comments
; <- comment.line.semicolon.isg-nc punctuation.definition.comment.isg-nc
; ^^^^^^^^^ comment.line.semicolon.isg-nc
N10 G00 G90 X0 Y0 Z100 (rapid to the start)
; <--- entity.name.label.block-number.isg-nc
;   ^^^ keyword.other.g-code.isg-nc
;       ^^^ keyword.other.g-code.isg-nc
;           ^ variable.parameter.address.isg-nc
;                  ^ constant.numeric.isg-nc
;                 ^ variable.parameter.address.isg-nc
;                  ^^^ constant.numeric.isg-nc
;                      ^ comment.block.parenthesis.isg-nc punctuation.definition.comment.begin.isg-nc
;                       ^^^^^^^^^^^^^^^^^^ comment.block.parenthesis.isg-nc - variable.parameter.address.isg-nc
;                                         ^ comment.block.parenthesis.isg-nc punctuation.definition.comment.end.isg-nc
N20 #MSG ["machine data ahead (not a real #MACHINE DATA)"]
;   ^^^^ keyword.control.directive.isg-nc
;        ^ punctuation.section.brackets.begin.isg-nc
;                             ^^^^^^^^^^^ string.quoted.double.isg-nc - comment
;                                         ^^^^^^^^^^^^^ string.quoted.double.isg-nc - keyword
;                                                        ^ punctuation.section.brackets.end.isg-nc
N30 $IF V.A.ACTPOS.X > 100
;   ^^^ keyword.control.flow.isg-nc
;       ^^^^^^^^^^^^ variable.other.nc-variable.isg-nc
;                    ^ keyword.operator.comparison.isg-nc
;                      ^^^ constant.numeric.isg-nc
N40   G01 X50 F1000
;     ^^^ keyword.other.g-code.isg-nc
;             ^ variable.parameter.address.isg-nc
;              ^^^^ constant.numeric.isg-nc
N50 $ENDIF
;   ^^^^^^ keyword.control.flow.isg-nc
N60 L CYCLE [NAME=SysDrill.ecy @P1=1 @P2=10]
;   ^ keyword.control.call.isg-nc
;                              ^^^ variable.parameter.cycle.isg-nc
;                                 ^ keyword.operator.assignment.isg-nc
N70 #MACHINE DATA SYN [AX=X P-AXIS-00209=80000]   (new rapid feed)
;   ^^^^^^^^^^^^^ meta.machine-data.isg-nc keyword.control.directive.machine-data.isg-nc
;                 ^^^ storage.modifier.syn.isg-nc
;                      ^^ variable.parameter.machine-data.isg-nc
;                           ^^^^^^^^^^^^ constant.other.parameter-id.isg-nc
;                                        ^^^^^ constant.numeric.isg-nc
;                                                  ^^^^^^^^^^^^^^ comment.block.parenthesis.isg-nc
N80 #MACHINE DATA SYN [AX=X AXPARAM="getriebe[0].vb_eilgang 80000"]
;                           ^^^^^^^ variable.parameter.machine-data.isg-nc
;                                   ^ string.quoted.double.isg-nc punctuation.definition.string.begin.isg-nc
;                                    ^^^^^^^^ string.quoted.double.isg-nc variable.other.key.isg-nc
;                                            ^ variable.other.key.isg-nc punctuation.section.brackets.begin.isg-nc
;                                                ^^^^^^^^^^ variable.other.key.isg-nc
;                                                           ^^^^^ string.quoted.double.isg-nc constant.numeric.isg-nc
N90 #MACHINE DATA [AXNR=3 P-AXIS-00209.1=80000]
;                  ^^^^ variable.parameter.machine-data.isg-nc
;                       ^ constant.numeric.isg-nc
;                         ^^^^^^^^^^^^^^ constant.other.parameter-id.isg-nc
N100 #MACHINE DATA SYN [AX=X AXPARAM="kenngr.swe_pos 15000000" WAIT]
;                                                              ^^^^ keyword.other.wait.isg-nc
N103 #MACHINE DATA SYN [AX=X AXPARAM V.L.par[1]]
;                                    ^^^^^^^^^^ variable.other.nc-variable.isg-nc
N110 G98 X-500 Y-200  ; within the configured limits
;    ^^^ keyword.other.g-code.isg-nc
;         ^^^^ constant.numeric.isg-nc
;                     ^^^^^^^^ comment.line.semicolon.isg-nc
N130 G90 G01 X10 ( an unclosed comment with G98 X99999 inside
;                                           ^^^ comment.block.parenthesis.isg-nc - keyword.other.g-code.isg-nc
;                                                      ^^^^^^ comment.block.parenthesis.isg-nc
N140 G01 X1 (outer (nested) still a comment) Y2
;                           ^^^^^^^^^^^^^^^ comment.block.parenthesis.isg-nc
;                                            ^ variable.parameter.address.isg-nc
N150 G01 X1 ( noqa: N003 -- reviewed )
;             ^^^^ keyword.other.directive.noqa.isg-nc
;                   ^^^^ constant.other.rule-code.isg-nc
M30
; <--- keyword.other.m-code.isg-nc
