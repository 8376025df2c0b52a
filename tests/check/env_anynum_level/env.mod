MODULE LevelSensor
    ! The level is 1, 2 or 3, chosen anew after every step of the program.
    VAR signalai AI_LEVEL;

    PROC init()
        SetAI AI_LEVEL, AnyNum(1, 3);
    ENDPROC

    PROC react()
        SetAI AI_LEVEL, AnyNum(1, 3);
    ENDPROC
ENDMODULE
