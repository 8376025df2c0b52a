MODULE optional_parameter_present
  ! Tests: an optional parameter \num Scale may be omitted; Present(Scale)
  ! tells whether the caller supplied it; with or without a leading comma.
  FUNC num area(num w, num h \num Scale)
    VAR num a;
    a := w * h;
    IF Present(Scale) a := a * Scale;
    RETURN a;
  ENDFUNC
  PROC main()
    TPWrite "plain=" \Num:=area(2, 3);
    TPWrite "scaled=" \Num:=area(2, 3 \Scale:=10);
    TPWrite "comma=" \Num:=area(2, 3, \Scale:=2);
  ENDPROC
ENDMODULE
