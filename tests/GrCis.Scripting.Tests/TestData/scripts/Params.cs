// Parameters from the user: "n=1.5, depth=3, mat=glass, rc".
Dictionary<string, string> p = Util.ParseKeyValueList(param);

double n = 1.6;
bool nOk = Util.TryParse(p, "n", ref n);

int depth = 5;
Util.TryParse(p, "depth", ref depth);

string mat = "diffuse";
Util.TryParse(p, "mat", ref mat);

bool rc = Util.TryParseBool(p, "rc");

context["n"] = n;
context["nOk"] = nOk;
context["depth"] = depth;
context["mat"] = mat;
context["rc"] = rc;
context[PropertyName.CTX_TOOLTIP] = "n=<double>, depth=<int>, mat={diffuse|glass}, rc";
