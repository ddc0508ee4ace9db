// Strict parameter reading: a wrong value stops the script with a clear message.
GrCis.Scripting.ScriptParameters p = new GrCis.Scripting.ScriptParameters(param);
double n = p.GetDouble("n", 1.6);
context["n"] = n;
