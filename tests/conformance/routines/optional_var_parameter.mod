MODULE optional_var_parameter
  ! Tests: an optional parameter may be a VAR parameter: when supplied, the
  ! routine writes through it to the caller's variable.
  PROC measure(num v \VAR num Twice)
    TPWrite "v=" \Num:=v;
    IF Present(Twice) Twice := 2 * v;
  ENDPROC
  PROC main()
    VAR num t := 0;
    measure 4;
    TPWrite "t=" \Num:=t;
    measure 5 \Twice:=t;
    TPWrite "t=" \Num:=t;
  ENDPROC
ENDMODULE
