// Fails at run time at top level.
Dictionary<string, string> p = Util.ParseKeyValueList(param);
if (p.Count == 0)
  throw new ArgumentException("this scene needs a parameter");
