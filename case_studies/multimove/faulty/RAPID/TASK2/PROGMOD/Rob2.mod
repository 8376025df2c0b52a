MODULE Rob2
    ! Robot 2 works in the zone it shares with the other robot.  The PLC task
    ! guards the door (req2, grant2); the robots keep each other out of the
    ! zone themselves, with the shared flag zone_busy: wait until it is
    ! down, then raise it.  Those are two steps, and the other robot may run
    ! between them: both see the zone free and both enter.
    PERS bool req2 := FALSE;
    PERS bool grant2 := FALSE;
    PERS bool zone_busy := FALSE;
    CONST robtarget pHome := [[600,400,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pZone := [[900,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        WHILE TRUE DO
            req2 := TRUE;
            WaitUntil grant2;
            WaitUntil NOT zone_busy;
            zone_busy := TRUE;
            WorkInZone;
            zone_busy := FALSE;
            req2 := FALSE;
            WaitUntil NOT grant2;
        ENDWHILE
    ENDPROC

    PROC WorkInZone()
        MoveJ pZone, v1000, fine, tool0;
        MoveJ pHome, v1000, fine, tool0;
    ENDPROC
ENDMODULE
