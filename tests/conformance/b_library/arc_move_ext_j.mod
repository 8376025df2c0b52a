MODULE MainModule
  ! Tests: ArcMoveExtJ (RobotWare Arc) moves only the external axes inside a weld, as
  ! MoveExtJ does outside one: the robot's joints keep their values. Its arguments are
  ! those a public gantry welding program passes (\ID, speeddata, zonedata), and the switch
  ! \Start a RobotWare add-in's weld passes to its first move.
  TASK PERS seamdata seam1:=[0.5,0.5,[5,0,24,120,0,0,0,0,0],0.5,1,10,0,5,[5,0,24,120,0,0,0,0,0],0,1,[5,0,24,120,0,0,0,0,0],0,0,[0,0,0,0,0,0,0,0,0],0];
  TASK PERS welddata weld1:=[6,0,[5,0,24,120,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  PERS tooldata tWeldGun:=[TRUE,[[0,0,350],[1,0,0,0]],[2,[0,0,200],[1,0,0,0],0,0,0]];
  CONST robtarget p10:=[[600,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget jHome:=[[10,20,30,0,40,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR jointtarget jGantry{2}:=[[[0,0,0,0,0,0],[1500,200,9E9,9E9,9E9,9E9]],
                              [[0,0,0,0,0,0],[2500,300,9E9,9E9,9E9,9E9]]];
  PROC main()
    MoveAbsJ jHome, v100, fine, tool0;
    ArcLStart p10, v100, seam1, weld1, fine, tWeldGun;
    ArcMoveExtJ jGantry{1}\ID:=10, v100, fine\Start;
    ArcMoveExtJ jGantry{2}\ID:=20, v100, z0;
    TPWrite "gantry at " \Num:=CJointT().extax.eax_a;
    TPWrite "axis 2 at " \Num:=CJointT().robax.rax_2;
  ENDPROC
ENDMODULE
