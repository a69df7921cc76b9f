// not a room of sim: the checker names the folder
#pragma once
