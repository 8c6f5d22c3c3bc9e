// main() of the golden-output program: the same on every target; the board
// file linked beside it decides where the bytes go (see board.h).
#include "tools/panel/board.h"
#include "tests/golden/golden.h"

int main(int, char**) { return golden::run_all(golden::board_write); }
