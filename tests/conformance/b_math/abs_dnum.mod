MODULE MainModule
  ! Tests: AbsDnum returns the absolute value of a dnum, exact beyond num's integer range.
  PROC main()
    VAR dnum big := -4294967295;
    VAR dnum frac := -0.25;
    TPWrite "big=" \Dnum:=AbsDnum(big);
    TPWrite "frac=" \Dnum:=AbsDnum(frac);
  ENDPROC
ENDMODULE
