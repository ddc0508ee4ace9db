using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Scripting;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.Completion;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.Host.Mef;
using Microsoft.CodeAnalysis.QuickInfo;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Editing;

/// <summary>
/// Roslyn's editor services for scene scripts: completion, signature help and quick info, for the script
/// dialect exactly as <see cref="ScriptHost"/> compiles it (the globals <c>scene</c>, <c>param</c>,
/// <c>context</c> and their older names, the same imports and references, the given modules), with the
/// library's doc comments. Each call works on its own snapshot of the text, so calls may overlap.
/// </summary>
public sealed class ScriptAssistant : IDisposable
{
  /// <summary>Longest completion list returned (the best matches of the typed word first).</summary>
  public const int MaxCompletions = 200;

  /// <summary>How many of a list's first entries carry their signature and documentation by default (the rest on <see cref="DescribeAsync"/>).</summary>
  public const int DescribedCompletions = 1;

  readonly AdhocWorkspace workspace;
  readonly DocumentId documentId;

  /// <param name="modules">Compiled module folders the scripts may use (<see cref="ScriptHost.Modules"/>).</param>
  public ScriptAssistant(IReadOnlyList<ScriptModule>? modules = null)
  {
    modules ??= [];
    workspace = new AdhocWorkspace(MefHostServices.DefaultHost);
    var projectId = ProjectId.CreateNewId();
    var parse = new CSharpParseOptions(LanguageVersion.Latest, DocumentationMode.Parse, SourceCodeKind.Script);
    var options = new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary,
      usings: ScriptCompilationInputs.Imports(modules), allowUnsafe: true, nullableContextOptions: NullableContextOptions.Disable);
    workspace.AddProject(ProjectInfo.Create(projectId, VersionStamp.Create(), "Scene", "Scene", LanguageNames.CSharp,
      isSubmission: true, compilationOptions: options, parseOptions: parse,
      metadataReferences: DocumentedReferences.For(modules), hostObjectType: typeof(ScriptGlobals)));
    documentId = DocumentId.CreateNewId(projectId);
    workspace.AddDocument(DocumentInfo.Create(documentId, "Scene.cs", sourceCodeKind: SourceCodeKind.Script,
      loader: TextLoader.From(TextAndVersion.Create(SourceText.From(""), VersionStamp.Create()))));
  }

  Document At(string source) => workspace.CurrentSolution.GetDocument(documentId)!.WithText(SourceText.From(source));

  static void CheckPosition(string source, int position)
  {
    ArgumentNullException.ThrowIfNull(source);
    if (position < 0 || position > source.Length)
      throw new ArgumentOutOfRangeException(nameof(position), position, $"a position in the text (0 to {source.Length})");
  }

  /// <summary>What may be typed at <paramref name="position"/>: members after a dot, names and keywords elsewhere, filtered by the word typed so far.</summary>
  /// <param name="described">How many of the first entries carry their signature and documentation.</param>
  public async Task<CompletionResult> CompleteAsync(string source, int position, int described = DescribedCompletions, CancellationToken cancel = default)
  {
    CheckPosition(source, position);
    Candidates found = await CandidatesAsync(source, position, cancel).ConfigureAwait(false);
    var entries = new List<CompletionEntry>();
    foreach (Candidate candidate in found.Ranked.Take(MaxCompletions))
    {
      string? detail = null, documentation = null;
      if (entries.Count < described)
        (detail, documentation) = await DescribeAsync(found, candidate, cancel).ConfigureAwait(false);
      entries.Add(new CompletionEntry(candidate.Label, candidate.Kind, detail, documentation));
    }
    return new CompletionResult(found.Span.Start, found.Span.End, entries);
  }

  /// <summary>The signature and documentation of the completion entry <paramref name="label"/> offered at <paramref name="position"/> (for an entry listed undescribed).</summary>
  public async Task<CompletionEntry?> DescribeAsync(string source, int position, string label, CancellationToken cancel = default)
  {
    CheckPosition(source, position);
    ArgumentNullException.ThrowIfNull(label);
    Candidates found = await CandidatesAsync(source, position, cancel).ConfigureAwait(false);
    Candidate? candidate = found.All.FirstOrDefault(c => c.Label == label);
    if (candidate is null)
      return null;
    (string? detail, string? documentation) = await DescribeAsync(found, candidate, cancel).ConfigureAwait(false);
    return new CompletionEntry(label, candidate.Kind, detail, documentation);
  }

  /// <summary>An entry: Roslyn's item, or a context key (<c>PropertyName.CTX_WIDTH</c>) offered where the context dictionary takes one.</summary>
  sealed record Candidate(string Label, string Kind, CompletionItem? Item, IFieldSymbol? Key);

  /// <summary>Every entry offered at a position, and those matching the typed word, best first.</summary>
  sealed record Candidates(Document Document, CompletionService Service, TextSpan Span, IReadOnlyList<Candidate> All, IReadOnlyList<Candidate> Ranked);

  async Task<Candidates> CandidatesAsync(string source, int position, CancellationToken cancel)
  {
    Document document = At(source);
    SyntaxNode root = (await document.GetSyntaxRootAsync(cancel).ConfigureAwait(false))!;
    // A name typed at the end of a line that the parser joins with the next line into a declaration: end its
    // statement there, so the word is what it is as typed, an expression (offsets before it are unchanged).
    int end = StatementEnds.Before(root, position);
    if (end >= 0)
    {
      document = At(source.Insert(end, ";"));
      root = (await document.GetSyntaxRootAsync(cancel).ConfigureAwait(false))!;
    }
    CompletionService service = CompletionService.GetService(document)
      ?? throw new InvalidOperationException("Roslyn's C# completion service is not available (Microsoft.CodeAnalysis.CSharp.Features missing).");
    CompletionList list = await service.GetCompletionsAsync(document, position, cancellationToken: cancel).ConfigureAwait(false);
    CompletionBoosts boosts = CompletionBoosts.At(root, position);
    SemanticModel? model = await document.GetSemanticModelAsync(cancel).ConfigureAwait(false);
    TargetTyping target = TargetTyping.At(model, root, position);
    TextSpan span = list.Span;
    if (list.ItemsList.Count == 0)
    {
      // Roslyn's empty list has no span: the word at the caret is what an entry would replace.
      SyntaxToken word = position > 0 ? root.FindToken(position - 1) : default;
      span = word.IsKind(SyntaxKind.IdentifierToken) && word.Span.End >= position ? word.Span : new TextSpan(position, 0);
    }
    string typed = source.Substring(span.Start, Math.Max(0, Math.Min(position, span.End) - span.Start));
    var all = new List<Candidate>();
    foreach (CompletionItem item in list.ItemsList)
      all.Add(new Candidate(Label(item), Kind(item.Tags), item, null));
    if (boosts.OffersKeys && await document.Project.GetCompilationAsync(cancel).ConfigureAwait(false) is { } compilation)
      foreach (IFieldSymbol key in CompletionBoosts.Keys(compilation))
        all.Add(new Candidate(CompletionBoosts.KeyClass + "." + key.Name, "constant", null, key));
    var ranked = new List<(int Rank, int Tier, int KindTier, bool Preselected, bool Fits, int Uses, Candidate Candidate)>();
    foreach (Candidate c in all)
    {
      string name = c.Item?.FilterText ?? c.Label;
      int rank = CompletionRanking.Rank(name, typed);
      if (c.Key is not null && CompletionRanking.Rank(c.Key.Name, typed) is int keyRank and >= 0 && (rank < 0 || keyRank < rank))
        rank = keyRank; // "CTX_W" finds PropertyName.CTX_WIDTH
      if (rank >= 0)
        ranked.Add((rank, boosts.Tier(name), boosts.KindTier(c.Kind), c.Item is not null && CompletionBoosts.Preselected(c.Item),
                    target.Asks && c.Item is not null && target.Fits(name), boosts.Uses(c.Key?.Name ?? name), c));
    }
    List<Candidate> best = ranked.OrderBy(r => r.Rank).ThenBy(r => r.Tier).ThenByDescending(r => r.Preselected).ThenByDescending(r => r.Fits).ThenBy(r => r.KindTier).ThenByDescending(r => r.Uses)
      .ThenBy(r => r.Candidate.Item?.SortText ?? r.Candidate.Label, StringComparer.OrdinalIgnoreCase)
      .ThenBy(r => r.Candidate.Label, StringComparer.Ordinal).Select(r => r.Candidate).ToList();
    return new Candidates(document, service, span, all, best);
  }

  static async Task<(string? Detail, string? Documentation)> DescribeAsync(Candidates found, Candidate candidate, CancellationToken cancel)
  {
    if (candidate.Key is { } key)
      return (key.ToDisplayString(SymbolDisplayFormat.CSharpShortErrorMessageFormat) + " = \"" + key.ConstantValue + "\"", DocComments.Summary(key));
    return Split(await found.Service.GetDescriptionAsync(found.Document, candidate.Item!, cancel).ConfigureAwait(false));
  }

  /// <summary>The overloads of the call or object creation around <paramref name="position"/>, or null outside one.</summary>
  public async Task<SignatureHelp?> SignatureAsync(string source, int position, CancellationToken cancel = default)
  {
    CheckPosition(source, position);
    Document document = At(source);
    SyntaxNode? root = await document.GetSyntaxRootAsync(cancel).ConfigureAwait(false);
    SemanticModel? model = await document.GetSemanticModelAsync(cancel).ConfigureAwait(false);
    return root is null || model is null ? null : Signatures.At(root, model, position, cancel);
  }

  /// <summary>The declaration and doc comment of the name at <paramref name="position"/>, or null where there is none.</summary>
  public async Task<HoverInfo?> HoverAsync(string source, int position, CancellationToken cancel = default)
  {
    CheckPosition(source, position);
    Document document = At(source);
    QuickInfoService? service = QuickInfoService.GetService(document);
    if (service is null)
      return null;
    QuickInfoItem? info = await service.GetQuickInfoAsync(document, position, cancel).ConfigureAwait(false);
    if (info is null || info.Sections.IsEmpty)
      return null;
    string text = info.Sections.FirstOrDefault(s => s.Kind == QuickInfoSectionKinds.Description)?.Text ?? info.Sections[0].Text;
    string? docs = info.Sections.FirstOrDefault(s => s.Kind == QuickInfoSectionKinds.DocumentationComments)?.Text;
    return new HoverInfo(info.Span.Start, info.Span.End, text, string.IsNullOrWhiteSpace(docs) ? null : docs);
  }

  /// <summary>The semantic model of <paramref name="source"/> compiled as a script here (tests compare the services with what the compiler binds).</summary>
  internal async Task<SemanticModel> ModelAsync(string source, CancellationToken cancel = default) =>
    (await At(source).GetSemanticModelAsync(cancel).ConfigureAwait(false))!;

  /// <summary>A bare Roslyn lookup of the names visible at a position, on a fresh snapshot (a benchmark's floor).</summary>
  internal async Task<int> LookupFloorAsync(string source, int position, CancellationToken cancel = default)
  {
    SemanticModel? model = await At(source).GetSemanticModelAsync(cancel).ConfigureAwait(false);
    return model?.LookupSymbols(position).Length ?? 0;
  }

  // Roslyn's description is the signature on the first line, then the documentation.
  static (string? Detail, string? Documentation) Split(CompletionDescription? description)
  {
    string text = description?.Text.Trim() ?? "";
    if (text.Length == 0)
      return (null, null);
    int newline = text.IndexOf('\n');
    if (newline < 0)
      return (text, null);
    string rest = text[(newline + 1)..].Trim();
    return (text[..newline].TrimEnd('\r'), rest.Length == 0 ? null : rest);
  }

  // What the entry shows and inserts, e.g. "List<>" (its prefix and suffix included).
  static string Label(CompletionItem item) => item.DisplayTextPrefix + item.DisplayText + item.DisplayTextSuffix;

  static readonly HashSet<string> AccessTags = new(StringComparer.Ordinal) { "Public", "Protected", "Private", "Internal" };

  static string Kind(ImmutableArray<string> tags) =>
    tags.FirstOrDefault(t => !AccessTags.Contains(t))?.ToLowerInvariant() ?? "text";

  public void Dispose() => workspace.Dispose();
}
