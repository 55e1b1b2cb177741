/* Links no entry point: the baseline capi/size.sh subtracts. */
#include "airlight.h"

int main(void) { return 0; }
