MODULE arithmetic_precedence
  ! Tests: * and / bind tighter than + and -; operators of one level
  ! associate to the left; parentheses override.
  PROC main()
    TPWrite "2+3*4=" \Num:=2 + 3 * 4;
    TPWrite "(2+3)*4=" \Num:=(2 + 3) * 4;
    TPWrite "10-4-3=" \Num:=10 - 4 - 3;
    TPWrite "12/2*3=" \Num:=12 / 2 * 3;
    TPWrite "20-6/2=" \Num:=20 - 6 / 2;
  ENDPROC
ENDMODULE
