MODULE MainModule
  ! Tests: Present guards the use of an optional parameter so a default can replace it.
  PROC main()
    TPWrite "area=" \Num:=Area(2, 3);
    TPWrite "scaled=" \Num:=Area(2, 3 \Scale:=10);
  ENDPROC

  FUNC num Area(num w, num h \num Scale)
    VAR num factor := 1;
    IF Present(Scale) factor := Scale;
    RETURN w * h * factor;
  ENDFUNC
ENDMODULE
