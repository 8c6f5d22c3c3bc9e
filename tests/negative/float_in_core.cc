// Must NOT compile under core/ rules (make check-poison): proves that the
// forced include core/integer_only.h rejects floating point.
int scaled(int x) {
  double k = 0.5;
  return static_cast<int>(x * k);
}
