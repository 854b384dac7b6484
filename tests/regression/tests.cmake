# vpsolve executable tests (bad input, short case runs); included from tests/CMakeLists.txt.
