namespace GrCis.Bench.Embree;

/// <summary>One measured line: a ray set, a query, a thread count, its speed, and its disagreements with Embree's single-ray query.</summary>
public sealed record EmbreeRow(string Rays, string Query, int Threads, double Mrays, int ReferenceHits, int Mismatches);
