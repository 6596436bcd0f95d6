// The source that builds the test suites' shared precompiled header
// (tests/CMakeLists.txt, fw_test_pch); it has nothing of its own.
