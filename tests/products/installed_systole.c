/* Built by check_install.sh against the installed libhdt. */
#include <hdt.h>
#include <math.h>
#include <stdio.h>

int main(void) {
  const double expected = 2 * acosh(1 + sqrt(2.0));
  const double got = hdt_systole(2);
  if (!(fabs(got - expected) <= 1e-14 * expected)) {
    fprintf(stderr, "hdt_systole(2) = %.17g, expected %.17g\n", got, expected);
    return 1;
  }
  printf("installed libhdt %s: hdt_systole(2) = %.17g\n", hdt_version_string(), got);
  return 0;
}
