//! Token rewrites of the reduction: names in the parts' expressions replaced by the flat
//! model's, and the flat model's expansion pointed at the parts' fields.

use std::collections::HashMap;

use proc_macro2::{Delimiter, Group, Ident, Span, TokenStream, TokenTree};

/// Replaces names in `tokens`: a single name (`vp`) or a dotted path (`gear.wa`), each looked
/// up in `map` as written with dots, the longest path first. A name after a dot (a method, a
/// field of something else) is left alone. A replacement of more than one token is
/// parenthesised. Every identifier gets the call site's span, so that the flat model's names
/// resolve alike wherever its parts were written.
pub fn rename(tokens: TokenStream, map: &HashMap<String, TokenStream>) -> TokenStream {
    let trees: Vec<TokenTree> = tokens.into_iter().collect();
    let mut out = Vec::with_capacity(trees.len());
    let mut i = 0;
    while i < trees.len() {
        match &trees[i] {
            TokenTree::Ident(ident) if !after_dot(&out) => {
                // The dotted path that starts here: `a . b . c`.
                let mut path = vec![ident.to_string()];
                let mut j = i + 1;
                while let (Some(TokenTree::Punct(p)), Some(TokenTree::Ident(next))) =
                    (trees.get(j), trees.get(j + 1))
                {
                    if p.as_char() != '.' {
                        break;
                    }
                    path.push(next.to_string());
                    j += 2;
                }
                let found =
                    (1..=path.len()).rev().find_map(|len| map.get(&path[..len].join(".")).map(|r| (len, r)));
                match found {
                    Some((len, replacement)) => {
                        let many = replacement.clone().into_iter().nth(1).is_some();
                        if many {
                            let group = Group::new(Delimiter::Parenthesis, respan(replacement.clone()));
                            out.push(TokenTree::Group(group));
                        } else {
                            out.extend(respan(replacement.clone()));
                        }
                        i += 2 * len - 1;
                    }
                    None => {
                        out.push(TokenTree::Ident(Ident::new(&ident.to_string(), Span::call_site())));
                        i += 1;
                    }
                }
            }
            TokenTree::Ident(ident) => {
                out.push(TokenTree::Ident(Ident::new(&ident.to_string(), Span::call_site())));
                i += 1;
            }
            TokenTree::Group(g) => {
                let mut group = Group::new(g.delimiter(), rename(g.stream(), map));
                group.set_span(g.span());
                out.push(TokenTree::Group(group));
                i += 1;
            }
            other => {
                out.push(other.clone());
                i += 1;
            }
        }
    }
    out.into_iter().collect()
}

fn after_dot(out: &[TokenTree]) -> bool {
    matches!(out.last(), Some(TokenTree::Punct(p)) if p.as_char() == '.')
}

/// Every identifier with the call site's span.
pub fn respan(tokens: TokenStream) -> TokenStream {
    tokens
        .into_iter()
        .map(|tree| match tree {
            TokenTree::Ident(ident) => TokenTree::Ident(Ident::new(&ident.to_string(), Span::call_site())),
            TokenTree::Group(g) => {
                let mut group = Group::new(g.delimiter(), respan(g.stream()));
                group.set_span(g.span());
                TokenTree::Group(group)
            }
            other => other,
        })
        .collect()
}

/// Points the expansion of the flat model at the composite's fields: `self.gear__ratio`
/// becomes `self.gear.ratio`, and every string that names `gear__ratio` names `gear.ratio`.
/// `fields` maps each flat field to the path of fields it stands for; `names` lists every
/// flat name with its dotted form, longest first.
pub fn point_at_fields(
    tokens: TokenStream,
    fields: &HashMap<String, Vec<String>>,
    names: &[(String, String)],
) -> TokenStream {
    let trees: Vec<TokenTree> = tokens.into_iter().collect();
    let mut out: Vec<TokenTree> = Vec::with_capacity(trees.len());
    for tree in trees {
        match tree {
            TokenTree::Ident(ident) if after_self_dot(&out) => match fields.get(&ident.to_string()) {
                Some(path) => {
                    let span = ident.span();
                    for (k, field) in path.iter().enumerate() {
                        if k > 0 {
                            out.push(TokenTree::Punct(proc_macro2::Punct::new(
                                '.',
                                proc_macro2::Spacing::Alone,
                            )));
                        }
                        out.push(TokenTree::Ident(Ident::new(field, span)));
                    }
                }
                None => out.push(TokenTree::Ident(ident)),
            },
            TokenTree::Group(g) => {
                let mut group = Group::new(g.delimiter(), point_at_fields(g.stream(), fields, names));
                group.set_span(g.span());
                out.push(TokenTree::Group(group));
            }
            TokenTree::Literal(literal) => out.push(TokenTree::Literal(display(literal, names))),
            other => out.push(other),
        }
    }
    out.into_iter().collect()
}

fn after_self_dot(out: &[TokenTree]) -> bool {
    match out {
        [.., TokenTree::Ident(s), TokenTree::Punct(p)] => s == "self" && p.as_char() == '.',
        _ => false,
    }
}

/// A string literal with every flat name replaced by its dotted form.
fn display(literal: proc_macro2::Literal, names: &[(String, String)]) -> proc_macro2::Literal {
    let Ok(lit) = syn::parse2::<syn::LitStr>(TokenTree::Literal(literal.clone()).into()) else {
        return literal;
    };
    let value = lit.value();
    if !value.contains("__") {
        return literal;
    }
    let mut text = value;
    for (flat, dotted) in names {
        if text.contains(flat.as_str()) {
            text = text.replace(flat.as_str(), dotted);
        }
    }
    let mut out = proc_macro2::Literal::string(&text);
    out.set_span(literal.span());
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    #[test]
    fn names_and_paths_are_replaced_and_methods_kept() {
        let map: HashMap<String, TokenStream> = [
            ("p".to_owned(), quote!(l__p)),
            ("gear.wa".to_owned(), quote!(gear__wa)),
            ("n".to_owned(), quote!(0.0 * x)),
        ]
        .into_iter()
        .collect();
        let out = rename(quote!(p.powi(2) + gear.wa - n / n.sin()), &map);
        assert_eq!(
            out.to_string(),
            quote!(l__p.powi(2) + gear__wa - (0.0 * x) / (0.0 * x).sin()).to_string()
        );
    }

    #[test]
    fn fields_are_pointed_at_and_strings_renamed() {
        let fields: HashMap<String, Vec<String>> =
            [("gear__ratio".to_owned(), vec!["gear".to_owned(), "ratio".to_owned()])].into_iter().collect();
        let names = vec![("gear__ratio".to_owned(), "gear.ratio".to_owned())];
        let out =
            point_at_fields(quote!(let r = self.gear__ratio; f("gear__ratio", gear__ratio)), &fields, &names);
        assert_eq!(
            out.to_string(),
            quote!(let r = self.gear.ratio; f("gear.ratio", gear__ratio)).to_string()
        );
    }
}
