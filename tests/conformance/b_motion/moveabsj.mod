MODULE MainModule
  ! Tests: MoveAbsJ moves the axes to a jointtarget; CJointT returns those joint angles.
  CONST jointtarget jt := [[10,20,30,0,45,-60],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR jointtarget now;
    MoveAbsJ jt, v100, fine, tool0;
    now := CJointT();
    TPWrite "rax_1=" \Num:=now.robax.rax_1;
    TPWrite "rax_2=" \Num:=now.robax.rax_2;
    TPWrite "rax_5=" \Num:=now.robax.rax_5;
    TPWrite "rax_6=" \Num:=now.robax.rax_6;
  ENDPROC
ENDMODULE
