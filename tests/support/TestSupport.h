#pragma once

#include <QString>

namespace vct::test {

/** The project's source tree (set by CTest), for test data. */
QString sourceDir();
/** shared/reference of the workspace; a test that needs it fails when it is missing. */
QString referenceDir();
/** Where tests write actual/diff images; created on demand. */
QString outputDir();

} // namespace vct::test
