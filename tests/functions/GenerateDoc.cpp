// Prints the registry table of docs/functions.md; tests/functions/update_doc.sh splices it in.
#include "DocTable.h"

#include <cstdio>

int main() {
    std::fputs(voxc::test::registryTable().c_str(), stdout);
    return 0;
}
