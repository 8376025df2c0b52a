MODULE MainModule
  ! Tests: StrOrder(S1, S2, Order) is TRUE when S1 sorts strictly before S2 in the character
  ! order given; equal strings give FALSE; a proper prefix sorts first.
  PROC main()
    TPWrite "first_second=" \Bool:=StrOrder("FIRST", "SECOND", STR_UPPER);
    TPWrite "second_first=" \Bool:=StrOrder("SECOND", "FIRST", STR_UPPER);
    TPWrite "equal=" \Bool:=StrOrder("SAME", "SAME", STR_UPPER);
    TPWrite "prefix=" \Bool:=StrOrder("AB", "ABC", STR_UPPER);
    TPWrite "custom=" \Bool:=StrOrder("B", "A", "BA");
  ENDPROC
ENDMODULE
