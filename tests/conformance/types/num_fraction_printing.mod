MODULE num_fraction_printing
  ! Tests: TPWrite \Num prints non-integral num values with at most 6
  ! significant digits, trailing zeros dropped.
  PROC main()
    VAR num x;
    x := 10 / 4;
    TPWrite "10/4=" \Num:=x;
    x := -7 / 2;
    TPWrite "-7/2=" \Num:=x;
    x := 1 / 3;
    TPWrite "1/3=" \Num:=x;
    x := 2 / 3;
    TPWrite "2/3=" \Num:=x;
    x := 0.125;
    TPWrite "x=" \Num:=x;
    x := 1.234567;
    TPWrite "x=" \Num:=x;
  ENDPROC
ENDMODULE
