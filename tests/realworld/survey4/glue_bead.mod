MODULE GlueBead
    ! A glue bead along a part's edge. The bead instruction comes from the dispensing
    ! library of the cell, a module that is not given, and the part's work object from
    ! its calibration module: the library call passes it as \WObj, as the motion
    ! instructions do, which is what tells its type.
    PERS tooldata tGlueGun := [TRUE,[[0,0,180],[1,0,0,0]],[2,[0,0,60],[1,0,0,0],0,0,0]];
    CONST robtarget pEdgeStart := [[300,-200,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pEdgeEnd := [[300,200,50],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR num beads := 0;

    PROC main()
        MoveJ Offs(pEdgeStart, 0, 0, 100), v1000, z50, tGlueGun;
        BeadL pEdgeStart, v100, fine, tGlueGun \WObj:=woPart;
        BeadL pEdgeEnd, v100, fine, tGlueGun \WObj:=woPart;
        beads := beads + 1;
        MoveJ Offs(pEdgeEnd, 0, 0, 100), v1000, z50, tGlueGun;
    ENDPROC
ENDMODULE
