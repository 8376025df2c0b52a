MODULE MainModule
  ! Tests: TPWrite \Dnum appends a dnum with double precision: integers beyond num's exact
  ! range print all digits.
  PROC main()
    VAR dnum big := 4294967295;
    VAR dnum huge := 1234567890123;
    VAR dnum frac := -0.125;
    TPWrite "big=" \Dnum:=big;
    TPWrite "huge=" \Dnum:=huge;
    TPWrite "frac=" \Dnum:=frac;
  ENDPROC
ENDMODULE
