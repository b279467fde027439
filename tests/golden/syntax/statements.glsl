#version 300 es
#define STEPS 4
float f(float x) {
  float acc = 0.0;
  for (int i = 0; i < STEPS; ++i) {
    if (x > 1.0) continue; else acc += x * float(i);
  }
  while (acc > 10.0) acc -= 1.0;
  do { acc++; } while (acc < 0.0);
  switch (int(acc)) {
    case 0: acc = -acc; break;
    default: ;
  }
  return acc > 2.0 ? acc : sqrt(acc).x;
}
