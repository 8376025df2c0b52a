MODULE Weld
    ! trackdata and ArcLTrack come with an option (ArcWare) the controller has installed;
    ! its modules are not in the backup
    PERS trackdata track1 := [0, FALSE, 50, [0,0,0,0,0,0,0,0,0], [0,0,0,0,0,0,0]];
    PERS bool bReady := FALSE;
    PROC main()
        ArcLTrack track1;
        bReady := TRUE;
    ENDPROC
ENDMODULE
