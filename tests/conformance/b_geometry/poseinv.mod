MODULE MainModule
  ! Tests: PoseInv inverts a frame: trans = -R^T * t (180 degrees about z: [10,20,-30]).
  PROC main()
    VAR pose p := [[10, 20, 30], [0, 0, 0, 1]];
    VAR pose shift := [[5, 6, 7], [1, 0, 0, 0]];
    VAR pose inv;
    inv := PoseInv(p);
    TPWrite "inv=" \Pos:=inv.trans;
    inv := PoseInv(shift);
    TPWrite "shift=" \Pos:=inv.trans;
    TPWrite "rot unchanged=" \Bool:=inv.rot = shift.rot;
  ENDPROC
ENDMODULE
