// SPDX-License-Identifier: BSD-3-Clause
// The object that carries the test programs' shared precompiled header (tests/CMakeLists.txt); no code of its
// own.
