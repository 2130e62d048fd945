#!/usr/bin/env python3
"""Lists function bodies longer than N lines (default 80) in the C++ files under the given folders
(default src): brace matching with comments, strings and preprocessor lines blanked. A function is a
'{' at namespace or class scope whose preceding code ends with ')' (and qualifiers). A heuristic for
reviews: the line numbers are exact, the name column may not be.

  python3 scripts/long_functions.py 80 src
"""
import re, sys, os
def strip(src):
    out=[];i=0;n=len(src)
    while i<n:
        c=src[i]
        if src.startswith('//',i):
            j=src.find('\n',i); j=n if j<0 else j; out.append(' '*(j-i)); i=j
        elif src.startswith('/*',i):
            j=src.find('*/',i+2); j=n if j<0 else j+2; out.append(re.sub(r'[^\n]',' ',src[i:j])); i=j
        elif c=='"' or c=="'":
            if c=='"' and i>0 and src[i-1]=='R':
                m=re.match(r'R"([^(]*)\(',src[i-1:]); d=m.group(1); end=src.find(')'+d+'"',i); j=end+len(d)+2
            else:
                j=i+1
                while j<n and src[j]!=c:
                    j+= 2 if src[j]=='\\' else 1
                j+=1
            out.append(re.sub(r'[^\n]',' ',src[i:j])); i=j
        else:
            out.append(c); i+=1
    return ''.join(out)
def scan(path, limit):
    s=strip(open(path,encoding='utf-8',errors='replace').read())
    # remove preprocessor lines
    s='\n'.join(' '*len(l) if l.lstrip().startswith('#') else l for l in s.split('\n'))
    res=[]; stack=[]  # entries: (kind, start_index)
    for m in re.finditer(r'[{}]',s):
        i=m.start()
        if s[i]=='{':
            before=s[:i].rstrip()
            inside_fn=any(k=='fn' for k,_ in stack)
            kind='block'
            if not inside_fn:
                tail=before[-200:]
                if re.search(r'\)\s*(const|noexcept|override|final|mutable|\s|->\s*[\w:<>,\s\*&]+)*$',tail) and not re.search(r'\b(if|for|while|switch|catch)\s*\([^()]*\)\s*$',tail):
                    kind='fn'
            stack.append((kind,i))
        else:
            if not stack: continue
            kind,start=stack.pop()
            if kind=='fn':
                l0=s.count('\n',0,start)+1; l1=s.count('\n',0,i)+1
                if l1-l0+1>limit:
                    # name: last identifier before '(' of signature
                    head=s[max(0,start-300):start]
                    mm=re.findall(r'([~\w:]+)\s*\(',head)
                    res.append((l1-l0+1,path,l0,mm[0] if mm else '?'))
    return res
limit=int(sys.argv[1]) if len(sys.argv)>1 else 80
roots=sys.argv[2:] or ['src']
allr=[]
for r in roots:
    for d,_,fs in os.walk(r):
        for f in fs:
            if f.endswith(('.cpp','.h')): allr+=scan(os.path.join(d,f),limit)
for n,p,l,name in sorted(allr,reverse=True): print(f"{n:4d} {p}:{l} {name}")
