// docs/functions.md carries the registry table exactly as the registry generates it, so a
// record cannot be added, renamed or retoleranced without the docs following
// (tests/functions/update_doc.sh regenerates it).
#include "DocTable.h"

#include "voxc/builtins/Functions.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace voxc {
namespace doc_test {

std::string readDoc() {
    std::ifstream in(std::string(VOXC_SOURCE_DIR) + "/docs/functions.md");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(functions_Doc, RegistryTableIsCurrent) {
    const std::string doc = readDoc();
    ASSERT_FALSE(doc.empty()) << "docs/functions.md is missing";
    const size_t begin = doc.find(test::kDocTableBegin);
    const size_t end = doc.find(test::kDocTableEnd);
    ASSERT_NE(begin, std::string::npos) << "docs/functions.md has no registry table";
    ASSERT_NE(end, std::string::npos);
    EXPECT_EQ(doc.substr(begin, end + std::string(test::kDocTableEnd).size() - begin), test::registryTable())
        << "run tests/functions/update_doc.sh <build dir>";
}

TEST(functions_Doc, EveryRecordIsNamedInTheDoc) {
    const std::string doc = readDoc();
    for (const FunctionInfo& f : functions()) EXPECT_NE(doc.find("`" + std::string(f.name) + "`"), std::string::npos) << f.name;
}

} // namespace doc_test
} // namespace voxc
