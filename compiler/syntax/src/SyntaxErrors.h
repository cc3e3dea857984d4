#pragma once
// Turns ANTLR's recognition errors into E0001 diagnostics with readable messages
// ("expected ';'", "unexpected ']'") instead of ANTLR's token-set dumps.
#include "voxc/syntax/Diagnostics.h"

#include <DefaultErrorStrategy.h>
#include <Lexer.h>

namespace voxc {

// The error strategy keeps ANTLR's recovery (single-token insertion and deletion, then
// resynchronisation) and replaces only how each error is worded and located.
class SyntaxErrorStrategy : public antlr4::DefaultErrorStrategy {
public:
    explicit SyntaxErrorStrategy(Diagnostics& diagnostics) : diagnostics_(diagnostics) {}

protected:
    void reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) override;
    void reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) override;
    void reportFailedPredicate(antlr4::Parser* parser, const antlr4::FailedPredicateException& e) override;
    void reportUnwantedToken(antlr4::Parser* parser) override;
    void reportMissingToken(antlr4::Parser* parser) override;

private:
    Diagnostics& diagnostics_;
};

// Reports characters no token can start with.
void reportUnexpectedCharacter(antlr4::Lexer& lexer, Diagnostics& diagnostics);

// The location of a token (1-based column, length in characters).
SourceLoc tokenLoc(const antlr4::Token& token);

} // namespace voxc
