MODULE MainModule
  ! Tests: arc weld moves (ArcLStart, ArcL with \Weave, ArcCEnd) move the robot as MoveL
  ! and MoveC do; the welding process is not modelled (ArcRefresh, with or without
  ! its tuning arguments, has no effect).
  TASK PERS seamdata seam1:=[0.5,0.5,[5,0,24,120,0,0,0,0,0],0.5,1,10,0,5,[5,0,24,120,0,0,0,0,0],0,1,[5,0,24,120,0,0,0,0,0],0,0,[0,0,0,0,0,0,0,0,0],0];
  TASK PERS welddata weld1:=[6,0,[5,0,24,120,0,0,0,0,0],[0,0,0,0,0,0,0,0,0]];
  TASK PERS weavedata weave1:=[1,0,3,4,0,0,0,0,0,0,0,0,0,0,0];
  PERS tooldata tWeldGun:=[TRUE,[[0,0,350],[1,0,0,0]],[2,[0,0,200],[1,0,0,0],0,0,0]];
  CONST robtarget p10:=[[600,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20:=[[600,100,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p30:=[[650,150,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    ArcLStart p10, v100, seam1, weld1, fine, tWeldGun;
    ArcL p20, v100, seam1, weld1 \Weave:=weave1, z1, tWeldGun \WObj:=wobj0;
    ArcRefresh;
    ArcRefresh \WeldSpeed:=12, \WeaveWidth:=3;
    ArcCEnd p20, p30, v100, seam1, weld1, fine, tWeldGun;
    TPWrite "weld done at x=" \Num:=CPos(\Tool:=tWeldGun).x;
  ENDPROC
ENDMODULE
