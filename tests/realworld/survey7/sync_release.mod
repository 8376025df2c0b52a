MODULE sync_release
    ! Survey round 7: a move that calls a procedure in the middle of its path, named by a
    ! string (MoveLSync). The procedure lives in a module that was not given; another one
    ! named the same way is declared here and must not be declared twice.
    CONST robtarget pDrop := [[400,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    PERS num nReleased := 0;

    PROC main()
        MoveLSync pDrop, v200, z10, tool0, "ReleaseClamp";
        MoveJSync pDrop, v200, z10, tool0, "CountDrop";
    ENDPROC

    PROC CountDrop()
        nReleased := nReleased + 1;
    ENDPROC
ENDMODULE
