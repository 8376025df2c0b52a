MODULE relational_operators
  ! Tests: the six relational operators on num, and that arithmetic is
  ! evaluated before comparison and comparison before AND.
  PROC main()
    TPWrite "3<5 " \Bool:=3 < 5;
    TPWrite "5<=5 " \Bool:=5 <= 5;
    TPWrite "5>=6 " \Bool:=5 >= 6;
    TPWrite "6>6 " \Bool:=6 > 6;
    TPWrite "4<>4 " \Bool:=4 <> 4;
    TPWrite "4=4.0 " \Bool:=4 = 4.0;
    TPWrite "2+3>4 AND 1<2 " \Bool:=2 + 3 > 4 AND 1 < 2;
  ENDPROC
ENDMODULE
