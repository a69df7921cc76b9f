// The translation unit that builds the test suite's precompiled header
// (tests/CMakeLists.txt, fourbar_test_pch); it has no code of its own.
