// The Monte Carlo MRI test with a clipping plane opening the head (see TestMapperMonteCarloBrain.cxx).
int RenderMonteCarloBrain(int argc, char* argv[], bool clip);

int TestMapperMonteCarloClipped(int argc, char* argv[])
{
  return RenderMonteCarloBrain(argc, argv, true);
}
