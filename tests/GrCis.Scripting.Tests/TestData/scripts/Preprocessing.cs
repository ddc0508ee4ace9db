// Preprocessing stage: runs once, stores the "simulation" in a free context key.
if (Util.TryParseBool(context, PropertyName.CTX_PREPROCESSING))
{
  int calls = 0;
  Util.TryParse(context, "preprocessCalls", ref calls);
  context["preprocessCalls"] = calls + 1;
  context["simulation"] = new List<double> { 1.0, 2.0, 3.0 };
  return;
}

// Regular call: the preprocessing result must be there.
List<double> simulation = context["simulation"] as List<double>;
if (simulation == null)
  throw new InvalidOperationException("preprocessing result missing");
context["regularSawSimulation"] = simulation.Count;

// Rendering overrides.
context[PropertyName.CTX_WIDTH]         = 320;
context[PropertyName.CTX_HEIGHT]        = 240;
context[PropertyName.CTX_SUPERSAMPLING] = 4;
context[PropertyName.CTX_START_ANIM]    = 0.0;
context[PropertyName.CTX_END_ANIM]      = 5.0;
context[PropertyName.CTX_FPS]           = 30.0;
context[PropertyName.CTX_TOOLTIP]       = "n=<double> (index of refraction)";

scene.BackgroundColor = new double[] { 0.1, 0.2, 0.3 };

// A top-level return before the end of the script.
if (simulation.Count > 0)
  return;

scene.BackgroundColor = new double[] { 1.0, 0.0, 0.0 };
