MODULE var_parameter_by_reference
  ! Tests: a VAR parameter is passed by reference: assignments inside the
  ! routine change the caller's variable immediately.
  VAR num global := 0;
  PROC swap(VAR num a, VAR num b)
    VAR num t;
    t := a;
    a := b;
    b := t;
  ENDPROC
  PROC setAndShow(VAR num x)
    x := 5;
    TPWrite "global seen inside=" \Num:=global;
  ENDPROC
  PROC main()
    VAR num x := 1;
    VAR num y := 2;
    swap x, y;
    TPWrite "x=" \Num:=x;
    TPWrite "y=" \Num:=y;
    setAndShow global;
  ENDPROC
ENDMODULE
