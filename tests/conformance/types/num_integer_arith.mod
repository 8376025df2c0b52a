MODULE num_integer_arith
  ! Tests: num arithmetic (+, -, *) on integers is exact and TPWrite \Num
  ! prints integral values without decimals (negative with a minus sign).
  PROC main()
    VAR num a := 7;
    VAR num b := 3;
    TPWrite "sum=" \Num:=a + b;
    TPWrite "diff=" \Num:=b - a;
    TPWrite "prod=" \Num:=a * b;
  ENDPROC
ENDMODULE
