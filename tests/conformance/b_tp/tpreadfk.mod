MODULE MainModule
  ! Tests: TPReadFK shows its prompt, then stores the number (1-5) of the function key chosen.
  PROC main()
    VAR num key;
    TPReadFK key, "Continue?", "Yes", "No", "Maybe", stEmpty, stEmpty;
    TEST key
    CASE 1:
      TPWrite "chose Yes";
    CASE 2:
      TPWrite "chose No";
    DEFAULT:
      TPWrite "chose key " \Num:=key;
    ENDTEST
  ENDPROC
ENDMODULE
