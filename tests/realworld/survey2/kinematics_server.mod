MODULE IkServer
  ! a command server whose inverse-kinematics command needs the robot model
  VAR jointtarget jtResult;
  VAR num nCommand;
  PROC main()
    TPReadNum nCommand, "command";
    TEST nCommand
    CASE 12:
      jtResult := CalcJointT([[400,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]], tool0, \WObj:=wobj0);
      TPWrite "ik " \Num:=jtResult.robax.rax_1;
    DEFAULT:
      TPWrite "ping";
    ENDTEST
  ENDPROC
ENDMODULE
