MODULE MainModule
  ! Tests: TPWrite \Num appends the number to the string: integers without decimals, negative
  ! numbers with a minus sign, fractions without trailing zeros.
  PROC main()
    VAR num count := 123456;
    TPWrite "n=" \Num:=5;
    TPWrite "neg=" \Num:=-7;
    TPWrite "zero=" \Num:=0;
    TPWrite "count=" \Num:=count;
    TPWrite "half=" \Num:=0.5;
    TPWrite "milli=" \Num:=0.001;
    TPWrite "" \Num:=2.25;
  ENDPROC
ENDMODULE
