using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.Linq;
using System.Threading;
using System.Threading.Tasks;
using GrCis.Scripting;
using GrCis.Scripting.Compilation;
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
      usings: ScriptCompiler.ScriptImports(modules), allowUnsafe: true, nullableContextOptions: NullableContextOptions.Disable);
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
    Document document = At(source);
    CompletionService service = CompletionService.GetService(document)
      ?? throw new InvalidOperationException("Roslyn's C# completion service is not available (Microsoft.CodeAnalysis.CSharp.Features missing).");
    CompletionList list = await service.GetCompletionsAsync(document, position, cancellationToken: cancel).ConfigureAwait(false);
    TextSpan span = list.Span;
    string typed = source.Substring(span.Start, Math.Max(0, Math.Min(position, span.End) - span.Start));
    var ranked = new List<(int Rank, CompletionItem Item)>();
    foreach (CompletionItem item in list.ItemsList)
    {
      int rank = CompletionRanking.Rank(item.FilterText, typed);
      if (rank >= 0)
        ranked.Add((rank, item));
    }
    var entries = new List<CompletionEntry>();
    foreach ((int _, CompletionItem item) in ranked.OrderBy(r => r.Rank).ThenBy(r => r.Item.SortText, StringComparer.OrdinalIgnoreCase)
               .ThenBy(r => r.Item.DisplayText, StringComparer.Ordinal).Take(MaxCompletions))
    {
      string? detail = null, documentation = null;
      if (entries.Count < described)
        (detail, documentation) = Split(await service.GetDescriptionAsync(document, item, cancel).ConfigureAwait(false));
      entries.Add(new CompletionEntry(Label(item), Kind(item.Tags), detail, documentation));
    }
    return new CompletionResult(span.Start, span.End, entries);
  }

  /// <summary>The signature and documentation of the completion entry <paramref name="label"/> offered at <paramref name="position"/> (for an entry listed undescribed).</summary>
  public async Task<CompletionEntry?> DescribeAsync(string source, int position, string label, CancellationToken cancel = default)
  {
    CheckPosition(source, position);
    ArgumentNullException.ThrowIfNull(label);
    Document document = At(source);
    CompletionService? service = CompletionService.GetService(document);
    if (service is null)
      return null;
    CompletionList list = await service.GetCompletionsAsync(document, position, cancellationToken: cancel).ConfigureAwait(false);
    CompletionItem? item = list.ItemsList.FirstOrDefault(i => Label(i) == label);
    if (item is null)
      return null;
    (string? detail, string? documentation) = Split(await service.GetDescriptionAsync(document, item, cancel).ConfigureAwait(false));
    return new CompletionEntry(label, Kind(item.Tags), detail, documentation);
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
