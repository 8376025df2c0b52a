MODULE LocationTarget
    ! The robot moves between a pick and a place position for ever.
    CONST robtarget p_pick := [[500, 0, 400], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST robtarget p_place := [[0, 500, 400], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    CONST pos near_pick := [500, 0, 400.4];
    CONST pos off_pick := [500, 0, 401];
    VAR bool holding := FALSE;

    PROC main()
        WHILE TRUE DO
            MoveJ p_pick, v1000, z50, tool0;
            holding := TRUE;
            MoveL p_place, v500, fine, tool0;
            holding := FALSE;
        ENDWHILE
    ENDPROC
ENDMODULE
