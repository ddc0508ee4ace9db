// Fails at run time inside a method declared in the script.
scene.BackgroundColor = new double[] { 0.0, 0.0, 0.0 };

double[] Pick(int index)
{
  double[] colors = { 1.0, 0.5 };
  return new double[] { colors[index] };
}

scene.BackgroundColor = Pick(7);
