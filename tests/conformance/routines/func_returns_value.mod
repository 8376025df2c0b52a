MODULE func_returns_value
  ! Tests: a FUNC returns the value of its RETURN expression, of its declared
  ! type (num, string, bool, pos).
  FUNC num area(num w, num h)
    RETURN w * h;
  ENDFUNC
  FUNC string label(num id)
    RETURN "part" + "#";
  ENDFUNC
  FUNC bool isBig(num v)
    RETURN v > 100;
  ENDFUNC
  FUNC pos middle(pos a, pos b)
    RETURN [(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2];
  ENDFUNC
  PROC main()
    TPWrite "area=" \Num:=area(3, 4);
    TPWrite label(1);
    TPWrite "big " \Bool:=isBig(area(20, 6));
    TPWrite "mid=" \Pos:=middle([0, 0, 0], [2, 4, 6]);
  ENDPROC
ENDMODULE
