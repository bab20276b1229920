#pragma once
// Where the tests find the source tree (examples, reference images, translations, docs): the
// AWB_SOURCE_DIR that CTest sets, else the checkout the tests were configured in. A function,
// not a compile definition: an absolute path on every test file's command line made each
// compilation's hash depend on where the checkout is, so that a clone elsewhere (CI's) reused
// none of them from ccache (cmake/BuildSpeed.cmake; the definition is in one generated file).
#include <QString>

namespace awb::test {
QString sourceDir();
} // namespace awb::test
