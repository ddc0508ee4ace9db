using System;
using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.Completion;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GrCis.Editing;

/// <summary>
/// What orders the entries that match the typed word equally well, before the alphabet: a context key where the
/// script's context dictionary takes one, Roslyn's preselection (the type a <c>new</c> should create), then the
/// names the script already uses, most used first (scripts repeat their calls: a second
/// <c>Matrix4d.CreateTranslation</c> is likelier than <c>CreateFromAxisAngle</c>).
/// </summary>
internal sealed class CompletionBoosts
{
  /// <summary>The keys a script sets, in the order scripts usually set them, then those the host sets for it to read.</summary>
  static readonly string[] Written =
  {
    "CTX_TOOLTIP", "CTX_WIDTH", "CTX_HEIGHT", "CTX_SUPERSAMPLING", "CTX_ALGORITHM", "CTX_START_ANIM", "CTX_END_ANIM", "CTX_FPS",
    "CTX_SYNTHESIZER", "CTX_TIME", "CTX_SCRIPT_PATH", "CTX_SCENE_NAME", "CTX_SCENE", "CTX_PREPROCESSING",
  };

  /// <summary>Keys set together: a script that sets one of a group sets the others next.</summary>
  static readonly string[][] Groups =
  {
    new[] { "CTX_WIDTH", "CTX_HEIGHT" },
    new[] { "CTX_START_ANIM", "CTX_END_ANIM", "CTX_FPS" },
  };

  /// <summary>The keys a script reads: those the host sets first.</summary>
  static readonly string[] Read =
  {
    "CTX_SCRIPT_PATH", "CTX_SCENE_NAME", "CTX_SCENE", "CTX_PREPROCESSING", "CTX_TIME",
    "CTX_TOOLTIP", "CTX_WIDTH", "CTX_HEIGHT", "CTX_SUPERSAMPLING", "CTX_ALGORITHM", "CTX_SYNTHESIZER", "CTX_START_ANIM", "CTX_END_ANIM", "CTX_FPS",
  };

  /// <summary>The class holding the keys and the node attributes' names.</summary>
  public const string KeyClass = "PropertyName";

  readonly Dictionary<string, int> uses;
  readonly string[]? keyOrder;     // in a context key's place: the keys in the order to offer them
  readonly HashSet<string> keysSet; // keys the script assigns elsewhere (set once, so offered after the others)
  readonly bool afterKeyClass;      // the word follows "PropertyName."
  readonly bool afterDot;

  CompletionBoosts(Dictionary<string, int> uses, string[]? keyOrder, HashSet<string> keysSet, bool afterKeyClass, bool afterDot)
  {
    this.afterDot = afterDot;
    this.uses = uses;
    this.keyOrder = keyOrder;
    this.keysSet = keysSet;
    this.afterKeyClass = afterKeyClass;
  }

  /// <summary>Whether the word at the caret is a key of the context dictionary (<c>context[</c>, <c>context.TryGetValue(</c> ...) not after a dot: <c>PropertyName.CTX_*</c> entries join the list.</summary>
  public bool OffersKeys => keyOrder is not null && !afterKeyClass;

  public static CompletionBoosts At(SyntaxNode root, int position)
  {
    SyntaxToken word = position > 0 ? root.FindToken(position - 1) : default;
    bool typing = word.IsKind(SyntaxKind.IdentifierToken) && word.Span.End >= position;
    var uses = new Dictionary<string, int>(StringComparer.Ordinal);
    var keysSet = new HashSet<string>(StringComparer.Ordinal);
    foreach (SyntaxToken token in root.DescendantTokens())
    {
      if (!token.IsKind(SyntaxKind.IdentifierToken) || typing && token.Span == word.Span)
        continue;
      uses[token.ValueText] = uses.GetValueOrDefault(token.ValueText) + 1;
      if (token.ValueText.StartsWith("CTX_", StringComparison.Ordinal) && token.Parent?.Parent is MemberAccessExpressionSyntax key &&
          KeyOf(key) is (ElementAccessExpressionSyntax or InvocationExpressionSyntax, true))
        keysSet.Add(token.ValueText);
    }
    // The expression being typed: the name (after a dot, the member access), or the dot's member access.
    SyntaxNode? expression = typing ? word.Parent : word.IsKind(SyntaxKind.DotToken) && word.Span.End == position ? word.Parent : null;
    bool afterKeyClass = false;
    if (expression?.Parent is MemberAccessExpressionSyntax ma && ma.Name == expression)
      expression = ma;
    if (expression is MemberAccessExpressionSyntax access)
      afterKeyClass = access.Expression is IdentifierNameSyntax { Identifier.ValueText: KeyClass } or MemberAccessExpressionSyntax { Name.Identifier.ValueText: KeyClass };
    string[]? order = null;
    if (expression is ExpressionSyntax e && (!typing || expression is not MemberAccessExpressionSyntax || afterKeyClass) && KeyOf(e) is (not null, bool written))
      order = written ? Written : Read;
    else if (expression is null && word.Parent is BaseArgumentListSyntax open && word.Span.End <= position &&
             (word.IsKind(SyntaxKind.OpenBracketToken) || word.IsKind(SyntaxKind.OpenParenToken)) && KeyOf(open, 0) is (not null, bool writes))
      order = writes ? Written : Read; // right after "context[", nothing typed yet
    bool afterDot = expression is MemberAccessExpressionSyntax || expression?.Parent is QualifiedNameSyntax q && q.Right == expression ||
                    word.IsKind(SyntaxKind.DotToken) && word.Span.End == position;
    return new CompletionBoosts(uses, order, keysSet, afterKeyClass, afterDot);
  }

  // The element access or call on the context dictionary that takes `key` as its first argument (or a helper taking the
  // dictionary, then the key), and whether it sets it.
  static (ExpressionSyntax? Owner, bool Written) KeyOf(ExpressionSyntax key) =>
    key.Parent is ArgumentSyntax { Parent: BaseArgumentListSyntax list } argument ? KeyOf(list, list.Arguments.IndexOf(argument)) : (null, false);

  static (ExpressionSyntax? Owner, bool Written) KeyOf(BaseArgumentListSyntax list, int argument)
  {
    // A helper given the dictionary and then a key reads it: Util.TryParseBool(context, PropertyName.CTX_PREPROCESSING).
    if (argument > 0 && list.Parent is InvocationExpressionSyntax helper && IsContext(list.Arguments[argument - 1].Expression))
      return (helper, false);
    if (argument != 0)
      return (null, false);
    switch (list.Parent)
    {
      case ElementAccessExpressionSyntax element when IsContext(element.Expression):
        // A write unless the element is read inside another expression (an unfinished line is taken as a write).
        bool written = element.Parent is ExpressionStatementSyntax or GlobalStatementSyntax ||
                       element.Parent is AssignmentExpressionSyntax assignment && assignment.Left == element;
        return (element, written);
      case InvocationExpressionSyntax { Expression: MemberAccessExpressionSyntax call } invocation when IsContext(call.Expression):
        return (invocation, call.Name.Identifier.ValueText is "Add" or "TryAdd");
      default:
        return (null, false);
    }
  }

  // The script's context dictionary under today's name or 2018's.
  static bool IsContext(ExpressionSyntax e) => e is IdentifierNameSyntax { Identifier.ValueText: "context" or "outParam" };

  /// <summary>Lower first: the context keys' place (in a key's place), else 0.</summary>
  public int Tier(string name)
  {
    if (keyOrder is null)
      // After PropertyName. elsewhere: a node attribute's name (SetAttribute) before the context keys.
      return afterKeyClass && name.StartsWith("CTX_", StringComparison.Ordinal) ? 1 : 0;
    if (afterKeyClass)
      return KeyTier(name);
    if (name == KeyClass)
      return 0;
    string key = name.StartsWith(KeyClass + ".", StringComparison.Ordinal) ? name[(KeyClass.Length + 1)..] : "";
    return key.Length > 0 ? 1 + KeyTier(key) : 1000;
  }

  int KeyTier(string key)
  {
    int at = Array.IndexOf(keyOrder!, key);
    if (at < 0)
      return 500;
    if (keysSet.Contains(key))
      return 100 + at;
    return Groups.Any(g => g.Contains(key) && g.Any(keysSet.Contains)) ? at - 50 : at;
  }

  /// <summary>
  /// After a dot: a namespace first (it holds many names), then members, then nested types (seldom what a dot
  /// after a type leads to: <c>Util.P</c> means <c>ParseKeyValueList</c> more often than <c>Pair&lt;&gt;</c>). Elsewhere 0.
  /// </summary>
  public int KindTier(string kind) =>
    !afterDot ? 0 : kind switch
    {
      "namespace" => 0,
      "class" or "structure" or "interface" or "enum" or "delegate" or "module" => 2,
      _ => 1,
    };

  /// <summary>How often the script uses the name elsewhere (the word being typed not counted).</summary>
  public int Uses(string name) => uses.GetValueOrDefault(name);

  /// <summary>Whether Roslyn preselects the item (the type after <c>new</c> that the target expects).</summary>
  public static bool Preselected(CompletionItem item) => item.Rules.MatchPriority >= MatchPriority.Preselect;

  /// <summary>The context keys of <c>PropertyName</c> in the compilation, as entries' names <c>PropertyName.CTX_*</c>.</summary>
  public static IReadOnlyList<IFieldSymbol> Keys(Compilation compilation) =>
    compilation.GetTypeByMetadataName("Rendering." + KeyClass)?.GetMembers().OfType<IFieldSymbol>()
      .Where(f => f.IsConst && f.Name.StartsWith("CTX_", StringComparison.Ordinal)).ToList() ?? (IReadOnlyList<IFieldSymbol>)[];
}
