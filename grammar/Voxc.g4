// The .vox surface syntax. Deliberately generic: a file is constants and named blocks, and a
// block holds assignments, nested blocks, bare names and rows. Which block may hold what is
// the checker's business (compiler/check), so that a misspelt key gets a "did you mean"
// instead of a parse error, and new blocks (lsystem, feature, ...) need no grammar change.
grammar Voxc;

file
    : item* EOF
    ;

item
    : constDecl
    | block
    ;

constDecl
    : CONST name=IDENT '=' expr ';'
    ;

// `world { ... }`, `grammar caves { ... }`, `rule r1 { ... }`, `layer { ... }`
block
    : kind=IDENT label=IDENT? '{' member* '}'
    ;

member
    : assignment
    | block
    | row
    | nameStatement
    ;

assignment
    : key=IDENT '=' value ';'
    ;

// A pipeline entry: `start;`
nameStatement
    : IDENT ';'
    ;

value
    : expr                                  # ScalarValue
    | '[' (value (',' value)*)? ']'         # ListValue
    ;

// One printed row of a symbol or transform: `[GEQ 0.5 & LT 0.9, IGN, ADD -0.5]`
row
    : '[' cell (',' cell)* ']'
    ;

cell
    : term ('&' term)*
    ;

term
    : op=IDENT expr?
    ;

expr
    : '(' expr ')'                          # ParenExpr
    | '-' expr                              # NegateExpr
    | expr op=('*' | '/') expr              # MulExpr
    | expr op=('+' | '-') expr              # AddExpr
    | NUMBER                                # NumberExpr
    | IDENT                                 # NameExpr
    ;

CONST  : 'const' ;
IDENT  : [a-zA-Z_] [a-zA-Z_0-9]* ;
NUMBER : DIGITS ('.' DIGITS?)? EXPONENT? | '.' DIGITS EXPONENT? ;

fragment DIGITS   : [0-9]+ ;
fragment EXPONENT : [eE] [+-]? DIGITS ;

LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
// Matched only when no `*/` follows; the parser driver reports it, the parser never sees it.
UNTERMINATED_COMMENT : '/*' ( ~'*' | '*'+ ~[*/] )* '*'* EOF -> channel(HIDDEN) ;
WS : [ \t\r\n\f]+ -> skip ;
