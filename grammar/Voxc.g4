// The .vox surface syntax. Deliberately generic: a file is constants and named blocks, and a
// block holds assignments, nested blocks, bare names, rows and weighted strings. Which block may hold what is
// the checker's business (compiler/check), so that a misspelt key gets a "did you mean"
// instead of a parse error, and new blocks (material, lsystem, ...) need no grammar change. Expressions
// (fields, functions) and `feature NAME = generator { ... }` have rules of their own.
grammar Voxc;

file
    : item* EOF
    ;

item
    : constDecl
    | functionDecl
    | fieldDecl
    | featureDecl
    | block
    ;

constDecl
    : CONST name=IDENT '=' expr ';'
    ;

// `fn ridge(v: float) -> float = 1 - abs(v);`
functionDecl
    : FN name=IDENT '(' (parameter (',' parameter)*)? ')' '->' result=IDENT '=' fieldExpr ';'
    ;

parameter
    : name=IDENT ':' type=IDENT
    ;

// `field ground = clamp(24 - y, 0, 1);`
fieldDecl
    : FIELD name=IDENT '=' fieldExpr ';'
    ;

// `feature arch1 = arch { start = [16, 16, 16]; }`: a parametric generator (compiler/check)
featureDecl
    : FEATURE name=IDENT '=' block
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
    | weightedString
    ;

// An L-system production or macro substitute: `"FLFLFZ" tunnel 1;` (type and weight optional).
weightedString
    : text=STRING (type=IDENT)? weight=expr? ';'
    ;

assignment
    : key=IDENT '=' value ';'
    ;

// A pipeline entry: `start;`, `overhang;`, or a field stage with its mode: `subtract cave;`,
// optionally followed by a clause word and its operand: `subtract cave material sand;`. The
// clause word is an IDENT so `material` stays usable as a block kind and a key.
nameStatement
    : (combine=IDENT)? name=IDENT (clause=IDENT operand=IDENT)? ';'
    ;

value
    : expr                                  # ScalarValue
    | STRING                                # StringValue
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

// Field expressions (fields and function bodies). Alternatives are listed from the tightest
// binding to the loosest; `let` and `?:` extend as far right as possible.
fieldExpr
    : '(' fieldExpr ')'                                         # FieldParen
    | callee=IDENT '(' (fieldExpr (',' fieldExpr)*)? ')'        # FieldCall
    | fieldExpr '.' swizzle=IDENT                               # FieldMember
    | op=('-' | '!') fieldExpr                                  # FieldUnary
    | fieldExpr op=('*' | '/') fieldExpr                        # FieldBinary
    | fieldExpr op=('+' | '-') fieldExpr                        # FieldBinary
    | fieldExpr op=('<' | '<=' | '>' | '>=') fieldExpr          # FieldBinary
    | fieldExpr op=('==' | '!=') fieldExpr                      # FieldBinary
    | fieldExpr op='&&' fieldExpr                               # FieldBinary
    | fieldExpr op='||' fieldExpr                               # FieldBinary
    | <assoc=right> fieldExpr '?' fieldExpr ':' fieldExpr       # FieldConditional
    | LET name=IDENT '=' fieldExpr IN fieldExpr                 # FieldLet
    | NUMBER                                                    # FieldNumber
    | IDENT                                                     # FieldName
    ;

CONST  : 'const' ;
FN     : 'fn' ;
FIELD  : 'field' ;
FEATURE : 'feature' ;
LET    : 'let' ;
IN     : 'in' ;
IDENT  : [a-zA-Z_] [a-zA-Z_0-9]* ;
// Text between double quotes on one line, without escapes: L-system strings hold `[ ] 0 \`.
STRING : '"' ~["\r\n]* '"' ;
NUMBER : DIGITS ('.' DIGITS?)? EXPONENT? | '.' DIGITS EXPONENT? ;

fragment DIGITS   : [0-9]+ ;
fragment EXPONENT : [eE] [+-]? DIGITS ;

LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
// Matched only when no `*/` follows; the parser driver reports it, the parser never sees it.
UNTERMINATED_COMMENT : '/*' ( ~'*' | '*'+ ~[*/] )* '*'* EOF -> channel(HIDDEN) ;
// A '"' with no closing quote on its line; the parser driver reports it.
UNTERMINATED_STRING : '"' ~["\r\n]* -> channel(HIDDEN) ;
WS : [ \t\r\n\f]+ -> skip ;
